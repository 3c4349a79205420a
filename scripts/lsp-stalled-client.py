#!/usr/bin/env python3
"""A language client that never reads (issue 34, item 5): opens a 3,000-location document,
sends 2,000 documentSymbol requests and prints the server's resident memory each second
for 10 s. Usage: scripts/lsp-stalled-client.py [EKB-BINARY] (default target/debug/ekb)."""
import json, subprocess, sys, threading, time
binary = sys.argv[1] if len(sys.argv) > 1 else "target/debug/ekb"
def frame(obj):
    b = json.dumps(obj).encode(); return b"Content-Length: %d\r\n\r\n" % len(b) + b
lines = []
for i in range(1, 3001):
    lines.append(f"robotLocationDescription {i} Place number {i}")
    lines.append(f"preGestureMessageEnglish {i} Hello at place {i}")
text = "\n".join(lines) + "\n"
p = subprocess.Popen([binary, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
def feed():
    try:
        p.stdin.write(frame({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{},"rootUri":None}}))
        p.stdin.write(frame({"jsonrpc":"2.0","method":"initialized","params":{}}))
        p.stdin.write(frame({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///tmp/ekb-stalled-client.dat","languageId":"ekb","version":1,"text":text}}}))
        for i in range(1, 2001):
            p.stdin.write(frame({"jsonrpc":"2.0","id":i,"method":"textDocument/documentSymbol","params":{"textDocument":{"uri":"file:///tmp/ekb-stalled-client.dat"}}}))
        p.stdin.flush()
    except Exception:
        pass
threading.Thread(target=feed, daemon=True).start()
for t in range(10):
    time.sleep(1)
    rss = [l for l in open(f"/proc/{p.pid}/status") if l.startswith("VmRSS")][0].split()[1]
    print(f"{t+1} s: {int(rss)//1024} MB", flush=True)
p.kill()
