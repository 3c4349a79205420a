//! The main loop: one thread, one message at a time, as rust-analyzer's and ruff's servers
//! began.
//!
//! - Until `initialize`, requests are answered "not initialized"; after `shutdown`, "shutting
//!   down"; `exit` ends the loop (cleanly only after `shutdown`, as the protocol says).
//! - Messages that arrive while one is handled wait in a queue. A `$/cancelRequest` takes
//!   its request out of the queue and answers it "cancelled" (a request being handled runs
//!   to its end: none takes long).
//! - Diagnostics are published when the queue is empty, so a burst of changes is checked
//!   once, at its end; a request that needs a check makes it at once, and the diagnostics
//!   of that check go out right after its answer.
//! - A handler that panics answers an internal error; the server goes on.

use std::collections::VecDeque;
use std::panic::{catch_unwind, AssertUnwindSafe};

use crossbeam_channel::Receiver;
use lsp_server::{ErrorCode, Message, Notification, Request, RequestId, Response, ResponseError};
use lsp_types::notification::{self as notify, Notification as _};
use lsp_types::request::{self as ask, Request as _};
use lsp_types::{
    CodeActionKind, CodeActionOptions, CodeActionProviderCapability, CompletionOptions,
    InitializeParams, InitializeResult, MessageType, OneOf, RenameOptions, ServerCapabilities,
    ServerInfo, ShowMessageParams, TextDocumentSyncCapability, TextDocumentSyncKind, Uri,
};
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::Value;

use super::documents::{Document, Documents};
use super::handlers::{self, code_actions, Answer, Snapshot};
use super::position::Encoding;
use super::transport::{Held, Incoming, Outbox};
use super::workspace::{self, Workspace};
use crate::context::Context;

/// How the session ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ending {
    /// `exit` after `shutdown`.
    Clean,
    /// `exit` without `shutdown`, or the client went away.
    Abrupt,
}

/// Serves one client until it says `exit` or goes away.
pub fn serve(incoming: &Receiver<Incoming>, outgoing: &Outbox, cli: &Context) -> Ending {
    let Some(mut server) = initialize(incoming, outgoing, cli) else {
        return Ending::Abrupt;
    };
    server.run(incoming)
}

/// Waits for `initialize` and answers it; `None` if the client leaves first.
fn initialize(incoming: &Receiver<Incoming>, outgoing: &Outbox, cli: &Context) -> Option<Server> {
    let send = |message: Message| {
        let _ = outgoing.send(message.into());
    };
    loop {
        let request = match incoming.recv().ok()? {
            Incoming::Unreadable(answer) => {
                let _ = outgoing.send(answer);
                continue;
            }
            Incoming::Message(Message::Request(request), _) => request,
            Incoming::Message(Message::Notification(n), _) if n.method == notify::Exit::METHOD => {
                return None
            }
            Incoming::Message(..) => continue,
        };
        if request.method != ask::Initialize::METHOD {
            send(error(
                request.id,
                ErrorCode::ServerNotInitialized,
                "the server is not initialized yet: send `initialize` first",
            ));
            continue;
        }
        let params: InitializeParams = match serde_json::from_value(request.params) {
            Ok(params) => params,
            Err(reason) => {
                send(error(
                    request.id,
                    ErrorCode::InvalidParams,
                    &reason.to_string(),
                ));
                continue;
            }
        };
        let (server, problems) = Server::new(&params, outgoing.clone(), cli);
        send(Response::new_ok(request.id, server.capabilities()).into());
        for problem in problems {
            server.tell(MessageType::WARNING, problem);
        }
        return Some(server);
    }
}

struct Server {
    outgoing: Outbox,
    encoding: Encoding,
    documents: Documents,
    workspace: Workspace,
    /// Whether the client fills in a code action's edit when it is chosen ("fix all" is
    /// then computed only if asked for).
    resolves_code_actions: bool,
    shut_down: bool,
    /// The last problem with the settings told to the user.
    settings_problem: Option<String>,
}

impl Server {
    fn new(params: &InitializeParams, outgoing: Outbox, cli: &Context) -> (Server, Vec<String>) {
        let capabilities = &params.capabilities;
        let offered = capabilities
            .general
            .as_ref()
            .and_then(|general| general.position_encodings.as_deref());
        let resolves_code_actions = capabilities
            .text_document
            .as_ref()
            .and_then(|text| text.code_action.as_ref())
            .and_then(|actions| actions.resolve_support.as_ref())
            .is_some_and(|resolve| resolve.properties.iter().any(|p| p == "edit"));
        let (workspace, problems) = Workspace::new(cli, workspace::root(params).as_deref());
        let server = Server {
            outgoing,
            encoding: Encoding::negotiate(offered),
            documents: Documents::default(),
            workspace,
            resolves_code_actions,
            shut_down: false,
            settings_problem: None,
        };
        (server, problems)
    }

    fn capabilities(&self) -> Value {
        let capabilities = ServerCapabilities {
            position_encoding: Some(self.encoding.kind()),
            text_document_sync: Some(TextDocumentSyncCapability::Kind(
                TextDocumentSyncKind::INCREMENTAL,
            )),
            hover_provider: Some(true.into()),
            completion_provider: Some(CompletionOptions {
                trigger_characters: Some(vec![" ".into(), ",".into()]),
                ..CompletionOptions::default()
            }),
            definition_provider: Some(OneOf::Left(true)),
            references_provider: Some(OneOf::Left(true)),
            rename_provider: Some(OneOf::Right(RenameOptions {
                prepare_provider: Some(true),
                work_done_progress_options: Default::default(),
            })),
            document_symbol_provider: Some(OneOf::Left(true)),
            document_formatting_provider: Some(OneOf::Left(true)),
            code_action_provider: Some(CodeActionProviderCapability::Options(CodeActionOptions {
                code_action_kinds: Some(vec![
                    CodeActionKind::QUICKFIX,
                    code_actions::fix_all_kind(),
                ]),
                resolve_provider: Some(true),
                work_done_progress_options: Default::default(),
            })),
            inlay_hint_provider: Some(OneOf::Left(true)),
            ..ServerCapabilities::default()
        };
        json(InitializeResult {
            capabilities,
            server_info: Some(ServerInfo {
                name: "ekb".into(),
                version: Some(env!("CARGO_PKG_VERSION").into()),
            }),
        })
    }

    fn run(&mut self, incoming: &Receiver<Incoming>) -> Ending {
        // Each message holds its bytes of the reader's budget until it is handled.
        let mut queue: VecDeque<(Message, Held)> = VecDeque::new();
        loop {
            if queue.is_empty() {
                self.publish(Checks::Make);
                match incoming.recv() {
                    Ok(next) => self.enqueue(next, &mut queue),
                    Err(_) => return self.ending(),
                }
            }
            while let Ok(next) = incoming.try_recv() {
                self.enqueue(next, &mut queue);
            }
            match queue.pop_front() {
                Some((Message::Request(request), _held)) => {
                    let id = request.id.clone();
                    let response = catch_unwind(AssertUnwindSafe(|| self.answer(request)))
                        .unwrap_or_else(|_| {
                            error(
                                id,
                                ErrorCode::InternalError,
                                "ekb failed on this request (a bug in ekb; please report it)",
                            )
                        });
                    self.send(response);
                }
                Some((Message::Notification(n), _)) if n.method == notify::Exit::METHOD => {
                    return self.ending()
                }
                Some((Message::Notification(notification), _held)) => self.notified(notification),
                Some((Message::Response(_), _)) | None => {}
            }
            // A request that needed a check made it: its diagnostics go now, not after the
            // requests still waiting.
            self.publish(Checks::Made);
        }
    }

    fn ending(&self) -> Ending {
        match self.shut_down {
            true => Ending::Clean,
            false => Ending::Abrupt,
        }
    }

    /// Queues what arrived, answering at once what cannot be read and the requests that are
    /// cancelled while they wait.
    fn enqueue(&self, next: Incoming, queue: &mut VecDeque<(Message, Held)>) {
        let (message, held) = match next {
            Incoming::Unreadable(answer) => {
                let _ = self.outgoing.send(answer);
                return;
            }
            Incoming::Message(message, held) => (message, held),
        };
        if let Message::Notification(n) = &message {
            if n.method == notify::Cancel::METHOD {
                let cancelled: Option<RequestId> = n
                    .params
                    .get("id")
                    .and_then(|id| serde_json::from_value(id.clone()).ok());
                let waiting = queue.iter().position(
                    |(m, _)| matches!(m, Message::Request(r) if Some(&r.id) == cancelled.as_ref()),
                );
                if let Some((Message::Request(request), _)) =
                    waiting.and_then(|at| queue.remove(at))
                {
                    self.send(error(request.id, ErrorCode::RequestCanceled, "cancelled"));
                }
                return;
            }
        }
        queue.push_back((message, held));
    }

    fn answer(&mut self, request: Request) -> Message {
        let id = request.id.clone();
        let result = match request.method.as_str() {
            ask::Initialize::METHOD => Err(response_error(
                ErrorCode::InvalidRequest,
                "the server is initialized already",
            )),
            ask::Shutdown::METHOD => {
                self.shut_down = true;
                Ok(Value::Null)
            }
            _ if self.shut_down => Err(response_error(
                ErrorCode::InvalidRequest,
                "the server is shutting down: only `exit` is expected now",
            )),
            ask::HoverRequest::METHOD => {
                self.on::<ask::HoverRequest>(request, handlers::hover::hover)
            }
            ask::Completion::METHOD => {
                self.on::<ask::Completion>(request, handlers::completion::completion)
            }
            ask::GotoDefinition::METHOD => {
                self.on::<ask::GotoDefinition>(request, handlers::navigation::definition)
            }
            ask::References::METHOD => {
                self.on::<ask::References>(request, handlers::navigation::references)
            }
            ask::PrepareRenameRequest::METHOD => {
                self.on::<ask::PrepareRenameRequest>(request, handlers::navigation::prepare_rename)
            }
            ask::Rename::METHOD => self.on::<ask::Rename>(request, handlers::navigation::rename),
            ask::DocumentSymbolRequest::METHOD => {
                self.on::<ask::DocumentSymbolRequest>(request, |s, _| handlers::symbols::symbols(s))
            }
            ask::Formatting::METHOD => {
                self.on::<ask::Formatting>(request, |s, _| handlers::formatting::formatting(s))
            }
            ask::InlayHintRequest::METHOD => {
                self.on::<ask::InlayHintRequest>(request, handlers::inlay_hints::inlay_hints)
            }
            ask::CodeActionRequest::METHOD => {
                let lazy = self.resolves_code_actions;
                self.on::<ask::CodeActionRequest>(request, |s, p| {
                    code_actions::code_actions(s, p, lazy)
                })
            }
            ask::CodeActionResolveRequest::METHOD => self
                .on::<ask::CodeActionResolveRequest>(request, |s, action| {
                    code_actions::resolve(s, action.clone())
                }),
            method => Err(response_error(
                ErrorCode::MethodNotFound,
                &format!("ekb does not answer `{method}`"),
            )),
        };
        Response {
            id,
            response_result: result,
        }
        .into()
    }

    /// Answers a request about one document with `handler`, given a snapshot of it.
    fn on<R>(
        &mut self,
        request: Request,
        handler: impl FnOnce(&Snapshot<'_, '_>, &R::Params) -> Answer<R::Result>,
    ) -> Answer<Value>
    where
        R: lsp_types::request::Request,
        R::Params: DeserializeOwned + AboutDocument,
    {
        let params: R::Params = serde_json::from_value(request.params)
            .map_err(|e| response_error(ErrorCode::InvalidParams, &e.to_string()))?;
        let uri = params.document().ok_or_else(|| {
            response_error(ErrorCode::InvalidParams, "the request names no document")
        })?;
        let answer = self.with_snapshot(&uri, |snapshot| handler(snapshot, &params).map(json));
        answer.unwrap_or_else(|| {
            Err(handlers::failed(format!(
                "ekb has not been told that {} is open: send `textDocument/didOpen` first",
                uri.as_str()
            )))
        })
    }

    /// Calls `f` with the open document at `uri`, checked; `None` if it is not open.
    fn with_snapshot<R>(&mut self, uri: &Uri, f: impl FnOnce(&Snapshot<'_, '_>) -> R) -> Option<R> {
        let document = self.documents.get_mut(uri)?;
        let path = document.path.clone();
        let name = path.as_ref().map_or_else(
            || uri.as_str().to_string(),
            |path| path.display().to_string(),
        );
        let workspace = &self.workspace;
        let mut settings = None;
        document.check(&name, || {
            let options = workspace.options(path.as_deref());
            let (options_in_force, rules) = options
                .as_ref()
                .map_or_else(|_| workspace.fallback_options(), Clone::clone);
            settings = Some(options.map(|_| ()));
            (options_in_force, rules, workspace.map(path.as_deref()))
        });
        // A broken `ekb.toml` is told once, not at every key typed.
        match settings {
            Some(Err(problem)) if self.settings_problem.as_ref() != Some(&problem) => {
                self.tell(MessageType::ERROR, problem.clone());
                self.settings_problem = Some(problem);
            }
            Some(Ok(())) => self.settings_problem = None,
            _ => {}
        }
        let document = self.documents.get(uri)?;
        let positions = document.positions(self.encoding);
        document.with_analysed(|analysed| {
            f(&Snapshot {
                uri,
                path: path.as_deref(),
                version: document.version,
                workspace: &self.workspace,
                positions,
                analysed,
            })
        })
    }

    fn notified(&mut self, notification: Notification) {
        let method = notification.method.clone();
        let handled = catch_unwind(AssertUnwindSafe(|| self.on_notification(notification)));
        if handled.is_err() {
            self.tell(
                MessageType::ERROR,
                format!("ekb failed on `{method}` (a bug in ekb; please report it); close and reopen the file"),
            );
        }
    }

    fn on_notification(&mut self, notification: Notification) {
        match notification.method.as_str() {
            notify::DidOpenTextDocument::METHOD => {
                if let Some(params) = self.params::<notify::DidOpenTextDocument>(notification) {
                    let document = params.text_document;
                    let path = workspace::file_path(&document.uri);
                    let opened = Document::new(document.version, path, document.text);
                    self.documents.open(document.uri, opened);
                }
            }
            notify::DidChangeTextDocument::METHOD => {
                if let Some(params) = self.params::<notify::DidChangeTextDocument>(notification) {
                    let uri = params.text_document.uri;
                    match self.documents.get_mut(&uri) {
                        Some(document) => document.change(
                            params.text_document.version,
                            params.content_changes,
                            self.encoding,
                        ),
                        None => self.tell(
                            MessageType::WARNING,
                            format!(
                                "ekb was sent changes to {}, which is not open",
                                uri.as_str()
                            ),
                        ),
                    }
                }
            }
            notify::DidCloseTextDocument::METHOD => {
                if let Some(params) = self.params::<notify::DidCloseTextDocument>(notification) {
                    let uri = params.text_document.uri;
                    if self.documents.close(&uri).is_some() {
                        let cleared = lsp_types::PublishDiagnosticsParams::new(uri, vec![], None);
                        self.notify::<notify::PublishDiagnostics>(cleared);
                    }
                }
            }
            // Saving changes nothing the server has not seen; the rest need no answer.
            _ => {}
        }
    }

    /// The parameters of a notification; a malformed one is told to the user and dropped
    /// (a notification has no answer).
    fn params<N: lsp_types::notification::Notification>(
        &self,
        notification: Notification,
    ) -> Option<N::Params> {
        match serde_json::from_value(notification.params) {
            Ok(params) => Some(params),
            Err(reason) => {
                self.tell(
                    MessageType::ERROR,
                    format!(
                        "ekb could not read a `{}` notification: {reason}",
                        N::METHOD
                    ),
                );
                None
            }
        }
    }

    /// Publishes the diagnostics of the documents that changed since they were last sent:
    /// of all of them (checking them now), or of those already checked.
    fn publish(&mut self, checks: Checks) {
        for uri in self.documents.unpublished() {
            let checked = self
                .documents
                .get(&uri)
                .and_then(|document| document.with_analysed(|_| ()))
                .is_some();
            if checks == Checks::Made && !checked {
                continue;
            }
            let published = catch_unwind(AssertUnwindSafe(|| {
                self.with_snapshot(&uri, handlers::diagnostics::publish)
            }));
            if let Some(document) = self.documents.get_mut(&uri) {
                document.published = true;
            }
            match published {
                Ok(Some(params)) => self.notify::<notify::PublishDiagnostics>(params),
                Ok(None) => {}
                Err(_) => self.tell(
                    MessageType::ERROR,
                    format!(
                        "ekb failed to check {} (a bug in ekb; please report it)",
                        uri.as_str()
                    ),
                ),
            }
        }
    }

    /// Shows the user a message (and logs it on standard error).
    fn tell(&self, kind: MessageType, message: String) {
        crate::stderr_line!("ekb lsp: {message}");
        self.notify::<notify::ShowMessage>(ShowMessageParams { typ: kind, message });
    }

    fn notify<N: lsp_types::notification::Notification>(&self, params: N::Params) {
        self.send(Notification::new(N::METHOD.to_string(), params).into());
    }

    fn send(&self, message: Message) {
        // A client that went away is noticed when its input ends.
        let _ = self.outgoing.send(message.into());
    }
}

/// Which documents [`Server::publish`] publishes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Checks {
    /// All: those not checked yet are checked now.
    Make,
    /// Those a request has checked already.
    Made,
}

/// Requests about one document: which.
pub trait AboutDocument {
    fn document(&self) -> Option<Uri>;
}

macro_rules! about_document {
    ($($params:ty => |$p:ident| $uri:expr),* $(,)?) => {
        $(impl AboutDocument for $params {
            fn document(&self) -> Option<Uri> {
                let $p = self;
                Some($uri.clone())
            }
        })*
    };
}

about_document! {
    lsp_types::HoverParams => |p| p.text_document_position_params.text_document.uri,
    lsp_types::CompletionParams => |p| p.text_document_position.text_document.uri,
    lsp_types::GotoDefinitionParams => |p| p.text_document_position_params.text_document.uri,
    lsp_types::ReferenceParams => |p| p.text_document_position.text_document.uri,
    lsp_types::TextDocumentPositionParams => |p| p.text_document.uri,
    lsp_types::RenameParams => |p| p.text_document_position.text_document.uri,
    lsp_types::DocumentSymbolParams => |p| p.text_document.uri,
    lsp_types::DocumentFormattingParams => |p| p.text_document.uri,
    lsp_types::InlayHintParams => |p| p.text_document.uri,
    lsp_types::CodeActionParams => |p| p.text_document.uri,
}

/// A code action to resolve names its document in its data (see [`code_actions`]).
impl AboutDocument for lsp_types::CodeAction {
    fn document(&self) -> Option<Uri> {
        let data = self.data.clone()?;
        serde_json::from_value::<code_actions::FixAllData>(data)
            .ok()
            .map(|data| data.uri)
    }
}

fn json(value: impl Serialize) -> Value {
    serde_json::to_value(value).unwrap_or(Value::Null)
}

fn response_error(code: ErrorCode, message: &str) -> ResponseError {
    ResponseError {
        code: code as i32,
        message: message.to_string(),
        data: None,
    }
}

fn error(id: RequestId, code: ErrorCode, message: &str) -> Message {
    Response::new_err(id, code as i32, message.to_string()).into()
}
