//! `ekb serve`: the knowledge base in a local web page, edited as forms, checked live by
//! the same library, saved back losslessly (SPEC §14).
//!
//! The server is [`tiny_http`]: small and synchronous, one request answered at a time on
//! the calling thread, no async runtime. One person edits one file on their own machine;
//! a check takes milliseconds, so one thread is plenty. It listens on 127.0.0.1 only and
//! answers only requests that pass [`security`]'s guards: the `Host`, the secret token, the
//! `Origin` of every POST and the cap on a body.
//!
//! Endpoints (JSON unless said):
//! - `GET /`, `/app.js`, `/app.css`: the page ([`assets`]), served by the server itself.
//! - `GET /api/file`: `{name, text, version, fields, tour}`, the file on disk now (`fields`:
//!   `[{id, key, value, line}]`, the value the robot reads for each key of each location;
//!   `tour`: the ids in order).
//! - `GET /api/version`: `{version}` of the file on disk now (the page asks every 3 s).
//! - `POST /api/check` `{text, edits?, tour?, add_locations?, remove_locations?}`: the
//!   locations added ([`locations::add`]), the edits applied to `text` with
//!   [`crate::edit::apply`], the locations removed, the tour line rewritten to `tour`
//!   ([`merge::set_tour`]), then `{text, fields, tour, check, reading_order, translations}`,
//!   `check` being exactly what `ekb check --format json` prints for that text,
//!   `reading_order` its findings as `[line, column, rule]` in the order `ekb check` shows
//!   them (errors first, each consequence after its cause), `translations` each language's
//!   status as `ekb translations --format json` counts it.
//! - `POST /api/save` `{base_version, text?, edits, tour?, add_locations?,
//!   remove_locations?}`: the same changes made on `text` (the page's
//!   version with the fixes it applied; else the version `base_version`) and written
//!   through the locking writer ([`crate::write`]); when the file changed on disk since,
//!   the edits are merged with it ([`merge`]) and the fixes dropped. 200 `{saved: true,
//!   conflicts: [], merged, fixes_dropped, name, text, version, fields, tour}` (the file as
//!   written), or, a value changed on both sides, 200 `{saved: false, conflicts: [{id, key,
//!   mine, theirs}], name, text, version, fields, tour}` (the file on disk) with nothing
//!   written; a conflict over the tour has id 0 and key `tourSpecification`, its values the
//!   ids in order.
//! - `GET /api/map`: the SVG of `ekb map` for the text last checked (else the file).

pub mod assets;
pub mod locations;
pub mod merge;
pub mod security;

use std::collections::VecDeque;
use std::io::Read;
use std::path::PathBuf;

use serde::Deserialize;
use serde_json::json;

use crate::check::{check_on_map, Summary};
use crate::context::{CommandError, Context};
use crate::draw::{self, svg::MapImage, Scene};
use crate::edit::{self, ValueEdit};
use crate::map::LabMap;
use crate::model::build::Options;
use crate::model::Key;
use crate::reader;
use crate::render::{self, Format, RenderOptions};
use crate::rules::selection::RuleSet;
use crate::source::SourceFile;
use crate::write;

use merge::{fields, version};
use security::{BodyError, TokenFound};

/// What the server serves: one file, read and checked as `ekb check` would.
pub struct Served<'c> {
    pub path: PathBuf,
    pub options: Options,
    pub rules: RuleSet,
    pub map: Option<LabMap>,
    pub context: &'c Context,
}

/// An answer, before it is sent.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reply {
    pub status: u16,
    pub content_type: &'static str,
    pub body: Vec<u8>,
    /// Hand the page the token in a cookie.
    pub set_cookie: bool,
}

impl Reply {
    fn new(status: u16, content_type: &'static str, body: impl Into<Vec<u8>>) -> Reply {
        Reply {
            status,
            content_type,
            body: body.into(),
            set_cookie: false,
        }
    }

    /// A refusal or an error, in plain text: why.
    pub fn plain(status: u16, reason: impl Into<String>) -> Reply {
        let mut body: String = reason.into();
        body.push('\n');
        Reply::new(status, "text/plain; charset=utf-8", body)
    }

    fn json(status: u16, value: &serde_json::Value) -> Reply {
        Reply::new(status, "application/json", value.to_string())
    }
}

/// The parts of a request the guards look at.
#[derive(Debug, Clone, Copy, Default)]
pub struct Head<'r> {
    pub post: bool,
    pub url: &'r str,
    pub host: Option<&'r str>,
    pub cookie: Option<&'r str>,
    pub origin: Option<&'r str>,
    pub length: Option<usize>,
}

/// Whether a request may be answered: `Err` with the refusal (a plain-text reason) of the
/// first guard that stops it, in the order they are asked: the `Host` (421), the token
/// (403), the `Origin` of a POST (403), the declared size (413); `Ok` with where the token
/// was (`TokenFound::Query`: the answer sets the cookie).
pub fn guard(head: &Head<'_>, port: u16, token: &str) -> Result<TokenFound, Reply> {
    if !security::host_allowed(head.host, port) {
        return Err(Reply::plain(
            421,
            format!(
                "refused: the Host header must be 127.0.0.1:{port}, localhost:{port} or \
                 [::1]:{port} (this server answers only its own address)"
            ),
        ));
    }
    let Some(found) = security::token_found(head.url, head.cookie, token) else {
        return Err(Reply::plain(
            403,
            "refused: no valid token; open the address `ekb serve` printed, with its ?token=",
        ));
    };
    if head.post && !security::origin_allowed(head.origin, port) {
        return Err(Reply::plain(
            403,
            format!(
                "refused: a request that changes anything needs the Origin of the page, \
                 http://127.0.0.1:{port}"
            ),
        ));
    }
    if head
        .length
        .is_some_and(|length| length > security::MAX_BODY)
    {
        return Err(too_large());
    }
    Ok(found)
}

fn too_large() -> Reply {
    Reply::plain(
        413,
        format!(
            "refused: the request is larger than {} MiB",
            security::MAX_BODY >> 20
        ),
    )
}

/// The server's state: what it serves, and the texts of the versions it handed the page
/// (to merge a save against the version the page loaded).
struct Server<'c> {
    served: Served<'c>,
    name: String,
    known: VecDeque<(String, String)>,
    /// The text last checked, for the map.
    last_checked: Option<String>,
}

/// How many versions of the file the server remembers.
const KNOWN_VERSIONS: usize = 16;

/// A value edit as the page sends it.
#[derive(Debug, Deserialize)]
struct EditIn {
    id: u32,
    key: String,
    value: String,
}

#[derive(Debug, Deserialize)]
struct CheckIn {
    text: String,
    #[serde(default)]
    edits: Vec<EditIn>,
    /// The tour's stops, in order, when the page changed them.
    #[serde(default)]
    tour: Option<Vec<u32>>,
    #[serde(flatten)]
    locations: LocationsIn,
}

/// Locations the page added (a first line is written for each, then the edits fill it) and
/// removed (every line of each).
#[derive(Debug, Default, Deserialize)]
struct LocationsIn {
    #[serde(default)]
    add_locations: Vec<u32>,
    #[serde(default)]
    remove_locations: Vec<u32>,
}

impl LocationsIn {
    /// `text` with the locations added (a description from `edits`, else a placeholder).
    fn add(&self, text: &str, edits: &[ValueEdit]) -> String {
        locations::add(text, &self.add_locations, |id| {
            edits
                .iter()
                .rev()
                .find(|edit| edit.id == id && edit.key == Key::RobotLocationDescription)
                .map_or_else(|| format!("New location {id}"), |edit| edit.value.clone())
        })
    }
}

#[derive(Debug, Deserialize)]
struct SaveIn {
    base_version: String,
    /// The text the edits apply to, when the page applied fixes to the version it loaded
    /// (else that version itself).
    #[serde(default)]
    text: Option<String>,
    edits: Vec<EditIn>,
    /// The tour's stops, in order, when the page changed them.
    #[serde(default)]
    tour: Option<Vec<u32>>,
    #[serde(flatten)]
    locations: LocationsIn,
}

/// Starts the server on 127.0.0.1:`port` (0: a free port), hands `announce` the address to
/// open (with the token), and answers requests until the process is stopped.
pub fn run(
    served: Served<'_>,
    port: u16,
    announce: impl FnOnce(&str) -> Result<(), CommandError>,
) -> Result<(), CommandError> {
    let failed = |what: &str, error: &dyn std::fmt::Display| {
        CommandError::Failed(format!("ekb serve: {what}: {error}"))
    };
    let token = security::new_token().map_err(|e| failed("no random token", &e))?;
    let http = tiny_http::Server::http(("127.0.0.1", port))
        .map_err(|e| failed(&format!("cannot listen on 127.0.0.1:{port}"), &e))?;
    let port = http
        .server_addr()
        .to_ip()
        .map(|address| address.port())
        .ok_or_else(|| failed("no port", &"not an IP socket"))?;
    let name = served.path.display().to_string();
    let mut server = Server {
        served,
        name,
        known: VecDeque::new(),
        last_checked: None,
    };
    announce(&format!("http://127.0.0.1:{port}/?token={token}"))?;
    for mut request in http.incoming_requests() {
        let header = |name: &'static str| {
            request
                .headers()
                .iter()
                .find(|header| header.field.equiv(name))
                .map(|header| header.value.as_str().to_string())
        };
        let (host, cookie, origin) = (header("Host"), header("Cookie"), header("Origin"));
        let post = *request.method() == tiny_http::Method::Post;
        let url = request.url().to_string();
        let head = Head {
            post,
            url: &url,
            host: host.as_deref(),
            cookie: cookie.as_deref(),
            origin: origin.as_deref(),
            length: request.body_length(),
        };
        let reply = match guard(&head, port, &token) {
            Err(refusal) => refusal,
            Ok(found) => {
                let length = head.length;
                let mut reply = server.answer(post, &url, length, request.as_reader());
                reply.set_cookie = found == TokenFound::Query;
                reply
            }
        };
        // A client gone before its answer is no failure of the server.
        let _ = request.respond(response(reply, &token));
    }
    Ok(())
}

/// The HTTP response of `reply`, with the headers every response carries.
fn response(reply: Reply, token: &str) -> tiny_http::Response<std::io::Cursor<Vec<u8>>> {
    let header = |name: &str, value: &str| {
        tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes())
            .expect("the server's own headers are valid")
    };
    let mut response = tiny_http::Response::from_data(reply.body)
        .with_status_code(reply.status)
        .with_header(header("Content-Type", reply.content_type))
        .with_header(header(
            "Content-Security-Policy",
            security::CONTENT_SECURITY_POLICY,
        ))
        .with_header(header("X-Content-Type-Options", "nosniff"))
        .with_header(header("Referrer-Policy", "no-referrer"))
        .with_header(header("Cache-Control", "no-store"))
        .with_header(header("Cross-Origin-Resource-Policy", "same-origin"));
    if reply.set_cookie {
        response.add_header(header("Set-Cookie", &security::cookie(token)));
    }
    response
}

impl Server<'_> {
    /// The answer to a request that passed the guards.
    fn answer(
        &mut self,
        post: bool,
        url: &str,
        length: Option<usize>,
        body: &mut dyn Read,
    ) -> Reply {
        let path = url.split_once('?').map_or(url, |(path, _)| path);
        let asset = |content_type, text: &'static str| Reply::new(200, content_type, text);
        match (post, path) {
            (false, "/") => asset("text/html; charset=utf-8", assets::INDEX_HTML),
            (false, "/app.js") => asset("text/javascript; charset=utf-8", assets::APP_JS),
            (false, "/app.css") => asset("text/css; charset=utf-8", assets::APP_CSS),
            (false, "/api/file") => self.file(),
            (false, "/api/version") => self.version(),
            (false, "/api/map") => self.map(),
            (true, "/api/check" | "/api/save") => {
                let body = match security::read_body(length, body, security::MAX_BODY) {
                    Ok(body) => body,
                    Err(BodyError::TooLarge) => return too_large(),
                    Err(BodyError::NotText) => {
                        return Reply::plain(400, "the request's body is not UTF-8")
                    }
                    Err(BodyError::Io(error)) => {
                        return Reply::plain(400, format!("cannot read the request: {error}"))
                    }
                };
                match path {
                    "/api/check" => self.check(&body),
                    _ => self.save(&body),
                }
            }
            (true, "/" | "/app.js" | "/app.css" | "/api/file" | "/api/version" | "/api/map")
            | (false, "/api/check" | "/api/save") => {
                Reply::plain(405, "method not allowed on this address")
            }
            _ => Reply::plain(404, "no such page: ekb serve serves one file's page"),
        }
    }

    /// The file as it is on disk now.
    fn read(&self) -> Result<SourceFile, Reply> {
        self.served
            .context
            .read(&self.served.path)
            .map_err(|error| Reply::plain(500, error.to_string()))
    }

    /// Remembers a version's text, to merge a later save against it.
    fn remember(&mut self, version: &str, text: &str) {
        if self.known.iter().any(|(known, _)| known == version) {
            return;
        }
        if self.known.len() == KNOWN_VERSIONS {
            self.known.pop_front();
        }
        self.known
            .push_back((version.to_string(), text.to_string()));
    }

    /// `{name, text, version, fields, tour}` of `text`, the file's on disk.
    fn on_disk(&mut self, text: &str) -> serde_json::Value {
        let version = version(text.as_bytes());
        self.remember(&version, text);
        let found = fields(text);
        json!({
            "name": self.name,
            "text": text,
            "version": version,
            "fields": found.fields,
            "tour": found.tour,
        })
    }

    fn file(&mut self) -> Reply {
        match self.read() {
            Ok(source) => {
                let value = self.on_disk(source.text());
                Reply::json(200, &value)
            }
            Err(reply) => reply,
        }
    }

    /// `{version}` of the file on disk now: how the page notices a change on disk.
    fn version(&mut self) -> Reply {
        match self.read() {
            Ok(source) => Reply::json(
                200,
                &json!({ "version": version(source.text().as_bytes()) }),
            ),
            Err(reply) => reply,
        }
    }

    fn check(&mut self, body: &str) -> Reply {
        let input: CheckIn = match serde_json::from_str(body) {
            Ok(input) => input,
            Err(error) => return bad_json(&error),
        };
        let edits = match value_edits(&input.edits) {
            Ok(edits) => edits,
            Err(reply) => return reply,
        };
        let text = input.locations.add(&input.text, &edits);
        let edits = without_empty_additions(&text, edits);
        let mut text = match edits.is_empty() {
            true => text,
            false => match edit::apply(&text, &edits) {
                Ok(edited) => edited.text,
                Err(error) => return Reply::plain(422, error.to_string()),
            },
        };
        text = locations::remove(&text, &input.locations.remove_locations);
        if let Some(tour) = input.tour.filter(|tour| *tour != fields(&text).tour) {
            text = merge::set_tour(&text, &tour);
        }
        let source = SourceFile::from_text(self.name.clone(), text);
        let checked = check_on_map(
            &source,
            &self.served.options,
            &self.served.rules,
            self.served.map.as_ref(),
        );
        let mut summary = Summary::default();
        summary.merge(&checked.summary());
        let catalog = crate::translations::Catalog::new(&checked);
        let translations: Vec<crate::translations::Status> = crate::robot::Language::ALL
            .iter()
            .map(|&language| catalog.status(language))
            .collect();
        drop(catalog);
        // The order people read the findings in: errors first, each consequence right after
        // its cause (as `ekb check` shows them), as [line, column, rule].
        let reading_order: Vec<(u32, u32, &str)> = render::FileReport::new(&checked)
            .in_reading_order()
            .iter()
            .map(|finding| (finding.region.line, finding.region.column, finding.rule))
            .collect();
        let mut findings = Vec::new();
        let rendered = render::render(
            Format::Json,
            std::slice::from_ref(&checked),
            &summary,
            &mut findings,
            &RenderOptions::default(),
        );
        drop(checked);
        if let Err(error) = rendered {
            return Reply::plain(500, format!("cannot render the findings: {error}"));
        }
        let check: serde_json::Value = match serde_json::from_slice(&findings) {
            Ok(value) => value,
            Err(error) => return Reply::plain(500, format!("findings not JSON: {error}")),
        };
        let text = source.into_text();
        let found = fields(&text);
        let value = json!({
            "text": text,
            "fields": found.fields,
            "tour": found.tour,
            "check": check,
            "reading_order": reading_order,
            "translations": translations,
        });
        self.last_checked = Some(text);
        Reply::json(200, &value)
    }

    fn save(&mut self, body: &str) -> Reply {
        let input: SaveIn = match serde_json::from_str(body) {
            Ok(input) => input,
            Err(error) => return bad_json(&error),
        };
        let edits = match value_edits(&input.edits) {
            Ok(edits) => edits,
            Err(reply) => return reply,
        };
        // Held from reading the file to writing it, as `ekb set` holds it.
        let _lock = match write::lock_to_rewrite(&self.served.path) {
            Ok(lock) => lock,
            Err(error) => return Reply::plain(500, error.to_string()),
        };
        let source = match self.read() {
            Ok(source) => source,
            Err(reply) => return reply,
        };
        let disk = source.text();
        let disk_version = version(disk.as_bytes());
        let merged = disk_version != input.base_version;
        // The page's fixes are kept when the file is still the version they were made on;
        // else only its value edits are merged, and the page shows the findings again.
        let fixes_dropped = merged && input.text.is_some();
        let (onto, edits, tour) = match (merged, input.text.as_deref()) {
            (false, fixed) => (fixed.unwrap_or(disk), edits, input.tour),
            (true, fixed) => {
                let base = fixed.or_else(|| {
                    self.known
                        .iter()
                        .find(|(version, _)| *version == input.base_version)
                        .map(|(_, text)| text.as_str())
                });
                let values = merge::merge(base, disk, &edits);
                let tour = match &input.tour {
                    Some(mine) => {
                        let base_tour = base.map(|base| fields(base).tour);
                        merge::merge_tour(base_tour.as_deref(), &fields(disk).tour, mine)
                    }
                    None => Ok(None),
                };
                match (values, tour) {
                    (Ok(edits), Ok(tour)) => (disk, edits, tour),
                    (values, tour) => {
                        let mut conflicts = values.err().unwrap_or_default();
                        conflicts.extend(tour.err());
                        // 200, not 409: the browser logs every 4xx as a console error, and a
                        // conflict is an answer, not a failure.
                        let mut value = self.on_disk(disk);
                        value["saved"] = json!(false);
                        value["conflicts"] = json!(conflicts);
                        return Reply::json(200, &value);
                    }
                }
            }
        };
        let onto = input.locations.add(onto, &edits);
        let edits = without_empty_additions(&onto, edits);
        let mut text = match edit::apply(&onto, &edits) {
            Ok(edited) => edited.text,
            Err(error) => return Reply::plain(422, error.to_string()),
        };
        text = locations::remove(&text, &input.locations.remove_locations);
        if let Some(tour) = tour.filter(|tour| *tour != fields(&text).tour) {
            text = merge::set_tour(&text, &tour);
        }
        if text != disk {
            let written = match source.stamp() {
                Some(stamp) => write::rewrite(&self.served.path, text.as_bytes(), stamp),
                None => write::write_atomically(&self.served.path, text.as_bytes()),
            };
            if let Err(error) = written {
                return Reply::plain(500, error.to_string());
            }
        }
        let mut value = self.on_disk(&text);
        value["saved"] = json!(true);
        value["conflicts"] = json!([]);
        value["merged"] = json!(merged);
        value["fixes_dropped"] = json!(fixes_dropped);
        Reply::json(200, &value)
    }

    /// The tour drawn on the map, as `ekb map` draws it, for the text last checked.
    fn map(&mut self) -> Reply {
        let text = match &self.last_checked {
            Some(text) => text.clone(),
            None => match self.read() {
                Ok(source) => source.into_text(),
                Err(reply) => return reply,
            },
        };
        let source = SourceFile::from_text(self.name.clone(), text);
        let map = self.served.map.as_ref();
        let checked = check_on_map(&source, &self.served.options, &self.served.rules, map);
        let loaded = reader::load(source.text().as_bytes(), checked.reader);
        let scene = Scene::new(&checked, &loaded, map);
        let svg = draw::svg::draw(&scene, MapImage::Embedded).svg;
        Reply::new(200, "image/svg+xml", svg)
    }
}

/// `edits` less those that would add an empty value: a field left empty where `text` has
/// no line for it adds no line.
fn without_empty_additions(text: &str, mut edits: Vec<ValueEdit>) -> Vec<ValueEdit> {
    if edits.iter().all(|edit| !edit.value.is_empty()) {
        return edits;
    }
    let found = fields(text).fields;
    edits.retain(|edit| {
        !edit.value.is_empty()
            || found
                .iter()
                .any(|field| field.id == edit.id && field.key == edit.key.name())
    });
    edits
}

fn bad_json(error: &serde_json::Error) -> Reply {
    Reply::plain(
        400,
        format!("the request is not the JSON expected: {error}"),
    )
}

/// The page's edits as [`ValueEdit`]s, or why one is no edit.
fn value_edits(edits: &[EditIn]) -> Result<Vec<ValueEdit>, Reply> {
    edits
        .iter()
        .map(|edit| {
            let key = match Key::from_name(&edit.key) {
                Some(Key::TourSpecification) | None => {
                    return Err(Reply::plain(
                        422,
                        format!("`{}` is no key of a location", edit.key.escape_debug()),
                    ))
                }
                Some(key) => key,
            };
            if edit.value.contains(['\n', '\r']) {
                return Err(Reply::plain(
                    422,
                    "a value is one line: it has no line break",
                ));
            }
            Ok(ValueEdit {
                id: edit.id,
                key,
                value: edit.value.trim_matches([' ', '\t']).to_string(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOKEN: &str = "00112233445566778899aabbccddeeff";

    fn head<'a>(url: &'a str, host: &'a str) -> Head<'a> {
        Head {
            url,
            host: Some(host),
            ..Head::default()
        }
    }

    #[test]
    fn the_guards_refuse_in_order_with_a_reason() {
        let url = format!("/?token={TOKEN}");
        let refused = guard(&head(&url, "evil.example:9"), 9, TOKEN).unwrap_err();
        assert_eq!(refused.status, 421);
        assert!(String::from_utf8_lossy(&refused.body).contains("Host"));
        assert_eq!(
            guard(&head("/", "127.0.0.1:9"), 9, TOKEN)
                .unwrap_err()
                .status,
            403
        );
        assert_eq!(
            guard(&head(&url, "127.0.0.1:9"), 9, TOKEN),
            Ok(TokenFound::Query)
        );
        let post = Head {
            post: true,
            origin: Some("http://evil.example"),
            ..head(&url, "localhost:9")
        };
        let refused = guard(&post, 9, TOKEN).unwrap_err();
        assert_eq!(refused.status, 403);
        assert!(String::from_utf8_lossy(&refused.body).contains("Origin"));
        let post = Head {
            origin: Some("http://localhost:9"),
            ..post
        };
        assert!(guard(&post, 9, TOKEN).is_ok());
        let big = Head {
            length: Some(security::MAX_BODY + 1),
            ..post
        };
        assert_eq!(guard(&big, 9, TOKEN).unwrap_err().status, 413);
    }

    #[test]
    fn an_empty_field_with_no_line_adds_no_line() {
        let edit = |key, value: &str| ValueEdit {
            id: 1,
            key,
            value: value.to_string(),
        };
        let text = "robotLocationDescription 1 Hall\n";
        let kept = without_empty_additions(
            text,
            vec![
                edit(Key::CulturalKnowledge, ""),
                edit(Key::RobotLocationDescription, ""),
                edit(Key::GestureArm, "left"),
            ],
        );
        assert_eq!(
            kept.iter().map(|edit| edit.key).collect::<Vec<_>>(),
            vec![Key::RobotLocationDescription, Key::GestureArm]
        );
    }

    #[test]
    fn edits_are_values_of_locations() {
        let edit = |key: &str, value: &str| EditIn {
            id: 1,
            key: key.to_string(),
            value: value.to_string(),
        };
        assert!(value_edits(&[edit("tourSpecification", "1 1")]).is_err());
        assert!(value_edits(&[edit("robotlocation", "1 1 1")]).is_err());
        assert!(value_edits(&[edit("robotLocationDescription", "a\nb")]).is_err());
        let made = value_edits(&[edit("robotLocationDescription", " Hall\t")]).unwrap();
        assert_eq!(made[0].value, "Hall");
    }
}
