#!/usr/bin/env python3
"""Language clients that never read what the server sends, and the server's memory meanwhile.

  scripts/lsp-stalled-client.py [EKB-BINARY]                 # 2,000 documentSymbol requests
  scripts/lsp-stalled-client.py --edits-mb 8 [EKB-BINARY]    # 8 MB didChange edits, for 20 s

The first opens a 3,000-location document and asks for its symbols 2,000 times; the second
sends whole-document edits of the given size as fast as the server takes them. Both print the
server's resident memory each second and its peak (VmHWM) at the end. EKB-BINARY defaults to
target/release/ekb."""
import argparse, json, subprocess, threading, time

parser = argparse.ArgumentParser()
parser.add_argument("binary", nargs="?", default="target/release/ekb")
parser.add_argument("--edits-mb", type=int, default=0)
args = parser.parse_args()
uri = "file:///tmp/ekb-stalled-client.dat"


def frame(obj):
    body = json.dumps(obj).encode()
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def document(locations):
    lines = []
    for i in range(1, locations + 1):
        lines.append(f"robotLocationDescription {i} Place number {i}")
        lines.append(f"preGestureMessageEnglish {i} Hello at place {i}")
    return "\n".join(lines) + "\n"


server = subprocess.Popen([args.binary, "lsp"], stdin=subprocess.PIPE,
                          stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)


def feed():
    try:
        send = server.stdin.write
        send(frame({"jsonrpc": "2.0", "id": 0, "method": "initialize",
                    "params": {"capabilities": {}, "rootUri": None}}))
        send(frame({"jsonrpc": "2.0", "method": "initialized", "params": {}}))
        text = document(3000)
        send(frame({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {
            "textDocument": {"uri": uri, "languageId": "ekb", "version": 1, "text": text}}}))
        if args.edits_mb:
            # About the size asked, a few lines differing from one edit to the next.
            base = document(args.edits_mb * 1024 * 1024 // 80)
            version = 1
            while True:
                version += 1
                edit = f"# edit {version}\n" + base
                send(frame({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
                    "textDocument": {"uri": uri, "version": version},
                    "contentChanges": [{"text": edit}]}}))
        else:
            for i in range(1, 2001):
                send(frame({"jsonrpc": "2.0", "id": i, "method": "textDocument/documentSymbol",
                            "params": {"textDocument": {"uri": uri}}}))
        server.stdin.flush()
    except Exception:
        pass


def status(field):
    with open(f"/proc/{server.pid}/status") as lines:
        return int(next(l for l in lines if l.startswith(field)).split()[1]) // 1024


threading.Thread(target=feed, daemon=True).start()
for second in range(20 if args.edits_mb else 10):
    time.sleep(1)
    print(f"{second + 1} s: {status('VmRSS')} MB", flush=True)
print(f"peak: {status('VmHWM')} MB")
server.kill()
