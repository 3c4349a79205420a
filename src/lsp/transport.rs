//! JSON-RPC over a byte stream, framed as LSP frames it (`Content-Length: N`, a blank line,
//! N bytes of JSON), on two threads: one reads, one writes.
//!
//! `lsp-server`'s own stdio transport stops at the first malformed message; an editor that
//! sends one (or a person typing into `ekb lsp`) would lose its server. This reader
//! answers each malformed message with the JSON-RPC error it deserves (a parse error, an
//! invalid request, `"id": null` when the id cannot be read) and reads on.
//!
//! Both queues are bounded: a client that sends requests and never reads the answers
//! fills the outgoing queue, the server then waits to send, stops taking requests, the
//! incoming messages fill their budget and the reader stops reading, so the client's own
//! writes wait. The server's memory stays what the queues hold, however long the client
//! stalls. What was read is bounded in bytes, not only in messages: each message read holds
//! its size of [`INCOMING_BUDGET`] until the server has handled it (a [`Held`]), so 8 MB
//! edits a stalled client keeps sending cost at most the budget, not 256 of them.

use std::io::{self, BufRead, Read, Write};
use std::sync::{Arc, Condvar, Mutex};
use std::thread;

use crossbeam_channel::{Receiver, Sender};
use lsp_server::{ErrorCode, Message, RequestId, Response};
use serde_json::Value;

/// The longest header line read: longer ones are malformed.
const MAX_HEADER_LINE: u64 = 8 * 1024;

/// The largest message read (a 512 MiB knowledge base, JSON-escaped, fits).
const MAX_CONTENT_LENGTH: usize = 1 << 30;

/// How many messages wait to be written at most: an answer can be large (the symbols of a
/// file of 3,000 locations), so few.
const OUTGOING_CAPACITY: usize = 16;

/// How many bytes of framed messages wait to be written at most (one larger message waits
/// alone): the diagnostics of a large document are megabytes.
const OUTGOING_BUDGET: usize = 64 << 20;

/// How many messages read wait for the server at most.
const INCOMING_CAPACITY: usize = 256;

/// How many bytes of messages read but not yet handled the server holds at most (one
/// larger message is read alone).
const INCOMING_BUDGET: usize = 64 << 20;

/// What the reader passes on.
#[derive(Debug)]
pub enum Incoming {
    /// A message, holding its bytes of the budget until dropped.
    Message(Message, Held),
    /// A message that could not be read, and the error that answers it.
    Unreadable(Outgoing),
}

/// What the writer sends.
#[derive(Debug)]
pub enum Outgoing {
    Message(Message),
    /// An error that answers a message whose id could not be read (`"id": null`).
    ErrorWithoutId {
        code: ErrorCode,
        message: String,
    },
}

impl From<Message> for Outgoing {
    fn from(message: Message) -> Outgoing {
        Outgoing::Message(message)
    }
}

/// The two ends of a connection and the writer's thread (joined to flush what is left).
#[derive(Debug)]
pub struct Transport {
    pub incoming: Receiver<Incoming>,
    pub outgoing: Outbox,
    writer: thread::JoinHandle<io::Result<()>>,
}

/// The server's end of the outgoing queue: each message is framed as it is sent, and the
/// frame holds its bytes of the outgoing budget until it is written.
#[derive(Debug, Clone)]
pub struct Outbox {
    frames: Sender<(Vec<u8>, Held)>,
    budget: Budget,
}

/// The writer has stopped: the client is gone.
#[derive(Debug)]
pub struct Disconnected;

impl Outbox {
    /// Waits for room in the queue and in its budget, then queues `message`.
    pub fn send(&self, message: Outgoing) -> Result<(), Disconnected> {
        let frame = framed(message);
        let held = self.budget.hold(frame.len());
        self.frames.send((frame, held)).map_err(|_| Disconnected)
    }
}

impl Transport {
    /// Reads messages from `input` and writes them to `output`, each on a thread of its own.
    /// The reader stops at the end of the input or after an `exit` notification.
    pub fn new(
        input: impl BufRead + Send + 'static,
        output: impl Write + Send + 'static,
    ) -> Transport {
        let (incoming_sender, incoming) = crossbeam_channel::bounded(INCOMING_CAPACITY);
        let (frames, outgoing_receiver) = crossbeam_channel::bounded(OUTGOING_CAPACITY);
        let outgoing = Outbox {
            frames,
            budget: Budget::new(OUTGOING_BUDGET),
        };
        thread::Builder::new()
            .name("ekb-lsp-reader".into())
            .spawn(move || read_messages(input, &incoming_sender))
            .expect("a thread can be started");
        let writer = thread::Builder::new()
            .name("ekb-lsp-writer".into())
            .spawn(move || write_messages(&outgoing_receiver, output))
            .expect("a thread can be started");
        Transport {
            incoming,
            outgoing,
            writer,
        }
    }

    /// Standard input and output.
    pub fn stdio() -> Transport {
        Transport::new(io::BufReader::new(io::stdin()), io::stdout())
    }

    /// Waits until everything sent has been written. (The reader is not waited for: it may
    /// be blocked on an input the client keeps open.)
    pub fn finish(self) -> io::Result<()> {
        drop(self.outgoing);
        self.writer.join().unwrap_or_else(|_| {
            Err(io::Error::other(
                "the thread writing to the client panicked",
            ))
        })
    }
}

/// Bytes of the messages read that the server has not handled yet, shared by the reader
/// (which waits for room) and the server (whose [`Held`]s give it back).
#[derive(Debug, Clone)]
struct Budget {
    state: Arc<(Mutex<usize>, Condvar)>,
    capacity: usize,
}

impl Budget {
    fn new(capacity: usize) -> Budget {
        Budget {
            state: Arc::new((Mutex::new(0), Condvar::new())),
            capacity,
        }
    }

    /// Waits until `bytes` more fit (or nothing is held: a message larger than the whole
    /// budget is read alone), and holds them.
    fn hold(&self, bytes: usize) -> Held {
        let (used, room) = &*self.state;
        let mut used = used.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        while *used > 0 && *used + bytes > self.capacity {
            used = room
                .wait(used)
                .unwrap_or_else(|poisoned| poisoned.into_inner());
        }
        *used += bytes;
        Held {
            budget: self.clone(),
            bytes,
        }
    }

    #[cfg(test)]
    fn used(&self) -> usize {
        *self.state.0.lock().unwrap()
    }
}

/// Bytes of the budget a message read holds; given back when it is dropped.
#[derive(Debug)]
pub struct Held {
    budget: Budget,
    bytes: usize,
}

impl Drop for Held {
    fn drop(&mut self) {
        let (used, room) = &*self.budget.state;
        let mut used = used.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        *used -= self.bytes;
        room.notify_all();
    }
}

fn read_messages(mut input: impl BufRead, incoming: &Sender<Incoming>) {
    read_within(&mut input, incoming, &Budget::new(INCOMING_BUDGET));
}

fn read_within(mut input: impl BufRead, incoming: &Sender<Incoming>, budget: &Budget) {
    loop {
        let next = match read_frame(&mut input) {
            Ok(Frame::End) | Err(_) => return,
            Ok(Frame::Body(body)) => {
                // The body and what it decodes to (its strings, as long): held until handled.
                let held = budget.hold(2 * body.len());
                match decode(&body) {
                    Ok(message) => Incoming::Message(message, held),
                    Err(answer) => Incoming::Unreadable(answer),
                }
            }
            Ok(Frame::Malformed(reason)) => Incoming::Unreadable(Outgoing::ErrorWithoutId {
                code: ErrorCode::ParseError,
                message: reason,
            }),
        };
        let is_exit =
            matches!(&next, Incoming::Message(Message::Notification(n), _) if n.method == "exit");
        if incoming.send(next).is_err() || is_exit {
            return;
        }
    }
}

fn write_messages(frames: &Receiver<(Vec<u8>, Held)>, mut output: impl Write) -> io::Result<()> {
    for (frame, _held) in frames {
        output.write_all(&frame)?;
        output.flush()?;
    }
    Ok(())
}

/// `message` as the client reads it: its header, a blank line, its JSON.
fn framed(message: Outgoing) -> Vec<u8> {
    let mut frame = Vec::new();
    match message {
        Outgoing::Message(message) => message
            .write(&mut frame)
            .expect("writing to memory does not fail"),
        Outgoing::ErrorWithoutId { code, message } => {
            let error = serde_json::json!({
                "jsonrpc": "2.0",
                "id": null,
                "error": { "code": code as i32, "message": message },
            });
            let text = error.to_string();
            frame = format!("Content-Length: {}\r\n\r\n{text}", text.len()).into_bytes();
        }
    }
    frame
}

/// One frame of the input.
#[derive(Debug, PartialEq)]
enum Frame {
    Body(Vec<u8>),
    /// A frame whose header makes no sense: why.
    Malformed(String),
    End,
}

/// Reads one frame: header lines up to a blank line, then the body the header announces.
fn read_frame(input: &mut impl BufRead) -> io::Result<Frame> {
    let mut length: Option<usize> = None;
    let mut malformed: Option<String> = None;
    let mut any_header = false;
    loop {
        let mut line = Vec::new();
        let read = input
            .by_ref()
            .take(MAX_HEADER_LINE)
            .read_until(b'\n', &mut line)?;
        if read == 0 {
            return Ok(match any_header {
                true => Frame::Malformed("the input ended inside a message's header".into()),
                false => Frame::End,
            });
        }
        let complete = line.ends_with(b"\n");
        let header = String::from_utf8_lossy(&line);
        let header = header.trim_end_matches(['\r', '\n']);
        if header.is_empty() && complete {
            if any_header {
                break;
            }
            continue; // A stray blank line between messages.
        }
        any_header = true;
        if !complete {
            malformed.get_or_insert_with(|| {
                format!("a header line longer than {MAX_HEADER_LINE} bytes")
            });
            continue;
        }
        match header.split_once(':') {
            Some((name, value)) if name.trim().eq_ignore_ascii_case("Content-Length") => {
                match value.trim().parse() {
                    Ok(n) => length = Some(n),
                    Err(_) => {
                        malformed.get_or_insert_with(|| {
                            format!(
                                "Content-Length `{}` is not a number of bytes",
                                excerpt(value.trim())
                            )
                        });
                    }
                }
            }
            Some(_) => {} // Content-Type, or a header of the future.
            None => {
                malformed.get_or_insert_with(|| {
                    format!(
                        "malformed header `{}`: a message starts with `Content-Length: N` and a blank line",
                        excerpt(header)
                    )
                });
            }
        }
    }
    let Some(length) = length else {
        return Ok(Frame::Malformed(malformed.unwrap_or_else(|| {
            "a message without Content-Length: a message starts with `Content-Length: N` and a blank line".into()
        })));
    };
    if length > MAX_CONTENT_LENGTH {
        io::copy(&mut input.by_ref().take(length as u64), &mut io::sink())?;
        return Ok(Frame::Malformed(format!(
            "a message of {length} bytes, more than the {MAX_CONTENT_LENGTH} ekb reads"
        )));
    }
    let mut body = vec![0; length];
    if let Err(error) = input.read_exact(&mut body) {
        return match error.kind() {
            io::ErrorKind::UnexpectedEof => Ok(Frame::End),
            _ => Err(error),
        };
    }
    Ok(match malformed {
        Some(reason) => Frame::Malformed(reason),
        None => Frame::Body(body),
    })
}

/// A message, or the error that answers a body that is not one.
fn decode(body: &[u8]) -> Result<Message, Outgoing> {
    if let Ok(message) = serde_json::from_slice::<Message>(body) {
        return Ok(message);
    }
    let value = match serde_json::from_slice::<Value>(body) {
        Ok(value) => value,
        Err(error) => {
            return Err(Outgoing::ErrorWithoutId {
                code: ErrorCode::ParseError,
                message: format!("the message is not JSON: {error}"),
            })
        }
    };
    let reason = "the message is not a JSON-RPC request, response or notification \
                  (a request has a numeric or string `id` and a string `method`)"
        .to_string();
    let id = value
        .get("id")
        .and_then(|id| serde_json::from_value::<RequestId>(id.clone()).ok());
    Err(match id {
        Some(id) => Outgoing::Message(Message::Response(Response::new_err(
            id,
            ErrorCode::InvalidRequest as i32,
            reason,
        ))),
        None => Outgoing::ErrorWithoutId {
            code: ErrorCode::InvalidRequest,
            message: reason,
        },
    })
}

/// The start of some text the client sent, for a message.
fn excerpt(text: &str) -> String {
    text.chars().take(40).flat_map(char::escape_debug).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frames(input: &[u8]) -> Vec<Frame> {
        let mut input = input;
        let mut frames = Vec::new();
        loop {
            match read_frame(&mut input).unwrap() {
                Frame::End => return frames,
                frame => frames.push(frame),
            }
        }
    }

    /// An output whose client never reads: every write waits until the test ends.
    struct Stalled(crossbeam_channel::Receiver<()>);

    impl Write for Stalled {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            let _ = self.0.recv();
            Err(io::ErrorKind::BrokenPipe.into())
        }

        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    /// Sends `answers` answers of `bytes` bytes each to a client that never reads, on a
    /// thread of their own: how many were queued after a while.
    fn queued_for_a_stalled_client(answers: usize, bytes: usize) -> usize {
        let (release, stalled) = crossbeam_channel::bounded(0);
        let transport = Transport::new(io::empty(), Stalled(stalled));
        let sent = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        let outbox = transport.outgoing.clone();
        let counter = sent.clone();
        let sender = thread::spawn(move || {
            for _ in 0..answers {
                let answer = Response::new_ok(RequestId::from(1), "x".repeat(bytes));
                if outbox
                    .send(Outgoing::Message(Message::Response(answer)))
                    .is_err()
                {
                    return;
                }
                counter.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
            }
        });
        std::thread::sleep(std::time::Duration::from_millis(300));
        let queued = sent.load(std::sync::atomic::Ordering::SeqCst);
        drop(release);
        let _ = transport.finish();
        let _ = sender.join();
        queued
    }

    #[test]
    fn answers_to_a_client_that_never_reads_wait_in_a_bounded_queue() {
        // The writer holds one answer, blocked; the queue holds the rest, then is full.
        let queued = queued_for_a_stalled_client(10_000, 1000);
        assert!(queued <= OUTGOING_CAPACITY + 1, "{queued} answers queued");
        // Large answers fill the budget in bytes first.
        let queued = queued_for_a_stalled_client(100, 20 << 20);
        assert!(
            queued <= OUTGOING_BUDGET / (20 << 20) + 1,
            "{queued} answers queued"
        );
    }

    #[test]
    fn messages_read_wait_for_the_server_within_a_budget_of_bytes() {
        // Ten 1 MB notifications, a budget of 3 MB: the reader stops after the third (each
        // holds twice its body) until the server drops what it has handled.
        let body = format!(
            r#"{{"jsonrpc":"2.0","method":"x","params":"{}"}}"#,
            "a".repeat(1 << 20)
        );
        let frame = format!("Content-Length: {}\r\n\r\n{body}", body.len());
        let input = io::Cursor::new(frame.repeat(10).into_bytes());
        let budget = Budget::new(3 * 2 * body.len());
        let (sender, receiver) = crossbeam_channel::bounded(INCOMING_CAPACITY);
        let reader_budget = budget.clone();
        let reader = thread::spawn(move || read_within(input, &sender, &reader_budget));
        let mut handled = Vec::new();
        while handled.len() < 3 {
            handled.push(receiver.recv().unwrap());
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
        assert!(receiver.try_recv().is_err(), "a fourth message was read");
        assert_eq!(budget.used(), 3 * 2 * body.len());
        drop(handled);
        let rest = receiver.iter().take(7).count();
        assert_eq!(rest, 7);
        reader.join().unwrap();
        assert_eq!(budget.used(), 0);
    }

    #[test]
    fn malformed_frames_are_reported_and_reading_goes_on() {
        let input = b"Content-Length: 2\r\n\r\n{}\
                      garbage\r\n\r\n\
                      Content-Length: x\r\n\r\n\
                      Content-Type: utf-8\nContent-Length: 4\n\n[1]\n\
                      Content-Length: 9\r\n\r\n{}";
        let frames = frames(input);
        assert_eq!(frames[0], Frame::Body(b"{}".to_vec()));
        assert!(matches!(&frames[1], Frame::Malformed(r) if r.contains("`garbage`")));
        assert!(matches!(&frames[2], Frame::Malformed(r) if r.contains("`x`")));
        assert_eq!(frames[3], Frame::Body(b"[1]\n".to_vec()));
        // A body cut short is the end of the input.
        assert_eq!(frames.len(), 4);
    }

    #[test]
    fn bodies_that_are_no_message_get_the_error_they_deserve() {
        let answer = |body: &str| match decode(body.as_bytes()) {
            Err(answer) => answer,
            Ok(message) => panic!("read {message:?}"),
        };
        assert!(matches!(
            answer("{not json"),
            Outgoing::ErrorWithoutId {
                code: ErrorCode::ParseError,
                ..
            }
        ));
        assert!(matches!(
            answer(r#"{"jsonrpc":"2.0","method":7}"#),
            Outgoing::ErrorWithoutId {
                code: ErrorCode::InvalidRequest,
                ..
            }
        ));
        match answer(r#"{"jsonrpc":"2.0","id":3,"method":[]}"#) {
            Outgoing::Message(Message::Response(response)) => {
                assert_eq!(response.id, RequestId::from(3));
                let error = response.response_result.unwrap_err();
                assert_eq!(error.code, ErrorCode::InvalidRequest as i32);
            }
            other => panic!("{other:?}"),
        }
    }
}
