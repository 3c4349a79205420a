//! The guards of `ekb serve` (SPEC §14, "Security"), as plain functions of a request's
//! headers so that they are tested without a network: the `Host` (against DNS rebinding),
//! the secret token (in the query the first time, then in a cookie), the `Origin` of a
//! request that changes anything, and the cap on a request's size.

use std::io::Read;

/// The name of the cookie that carries the token.
pub const COOKIE: &str = "ekb_token";

/// The largest request body the server reads: 8 MiB (a knowledge base of some thousands of
/// locations, sent whole to be checked).
pub const MAX_BODY: usize = 8 << 20;

/// The policy every response carries: nothing from the network, no inline script or style.
pub const CONTENT_SECURITY_POLICY: &str = "default-src 'none'; script-src 'self'; \
     style-src 'self'; img-src 'self' data:; connect-src 'self'; base-uri 'none'; \
     form-action 'none'; frame-ancestors 'none'";

/// The host names the server answers to, each with its port.
const LOOPBACK_NAMES: [&str; 3] = ["127.0.0.1", "localhost", "[::1]"];

/// Whether `host` (the `Host` header) is this server's own: `127.0.0.1:PORT`,
/// `localhost:PORT` or `[::1]:PORT`. Any other name (a DNS name that rebinds to 127.0.0.1)
/// is refused, and so is a request with no `Host`.
pub fn host_allowed(host: Option<&str>, port: u16) -> bool {
    let Some(host) = host else {
        return false;
    };
    let host = host.trim();
    LOOPBACK_NAMES.iter().any(|name| {
        // `get`, not slicing: a byte of a multi-byte character is no boundary.
        host.get(..name.len())
            .is_some_and(|start| start.eq_ignore_ascii_case(name))
            && host.get(name.len()..) == Some(format!(":{port}").as_str())
    })
}

/// Whether `origin` (the `Origin` header) is the page's own: `http://` and an allowed host.
/// A request that changes anything (every POST) needs one.
pub fn origin_allowed(origin: Option<&str>, port: u16) -> bool {
    match origin.and_then(|origin| origin.trim().strip_prefix("http://")) {
        Some(host) => host_allowed(Some(host), port),
        None => false,
    }
}

/// A new secret token: 128 bits from the operating system's random source (`/dev/urandom`),
/// in hex.
pub fn new_token() -> std::io::Result<String> {
    let mut bytes = [0u8; 16];
    std::fs::File::open("/dev/urandom")?.read_exact(&mut bytes)?;
    Ok(bytes.iter().map(|byte| format!("{byte:02x}")).collect())
}

/// Where a request's token was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TokenFound {
    /// In the query (`?token=…`): the page's first request; the answer sets the cookie.
    Query,
    /// In the cookie.
    Cookie,
}

/// Whether the request of `url` with `cookie` (the `Cookie` header) carries `token`, and
/// where; `None`: it does not (refused with 403).
pub fn token_found(url: &str, cookie: Option<&str>, token: &str) -> Option<TokenFound> {
    let in_cookie = cookie.is_some_and(|cookie| {
        cookie.split(';').any(|pair| {
            pair.trim()
                .strip_prefix(COOKIE)
                .and_then(|rest| rest.strip_prefix('='))
                .is_some_and(|value| same(value.trim(), token))
        })
    });
    if in_cookie {
        return Some(TokenFound::Cookie);
    }
    let query = url.split_once('?').map_or("", |(_, query)| query);
    let in_query = query.split('&').any(|pair| {
        pair.strip_prefix("token=")
            .is_some_and(|value| same(value, token))
    });
    in_query.then_some(TokenFound::Query)
}

/// The `Set-Cookie` value that hands the page the token.
pub fn cookie(token: &str) -> String {
    format!("{COOKIE}={token}; Path=/; HttpOnly; SameSite=Strict")
}

/// Compares in a time that does not depend on where the two differ.
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len()
        && a.bytes()
            .zip(b.bytes())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
}

/// Why a body was not read.
#[derive(Debug)]
pub enum BodyError {
    /// Larger than [`MAX_BODY`] (413).
    TooLarge,
    /// Not UTF-8 (400).
    NotText,
    Io(std::io::Error),
}

/// Reads a request's body of declared `length` from `reader`, at most `cap` bytes: a body
/// declared larger, or found larger, is refused before more is read.
pub fn read_body(
    length: Option<usize>,
    reader: &mut dyn Read,
    cap: usize,
) -> Result<String, BodyError> {
    if length.is_some_and(|length| length > cap) {
        return Err(BodyError::TooLarge);
    }
    let mut bytes = Vec::new();
    reader
        .take(cap as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(BodyError::Io)?;
    if bytes.len() > cap {
        return Err(BodyError::TooLarge);
    }
    String::from_utf8(bytes).map_err(|_| BodyError::NotText)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_loopback_names_with_the_port_are_hosts() {
        for host in [
            "127.0.0.1:8080",
            "localhost:8080",
            "LOCALHOST:8080",
            "[::1]:8080",
        ] {
            assert!(host_allowed(Some(host), 8080), "{host}");
        }
        for host in [
            "127.0.0.1:8081",
            "127.0.0.1",
            "localhost",
            "evil.example:8080",
            "localhost.evil.example:8080",
            "127.0.0.1:8080.evil.example",
            "127.0.0.2:8080",
            "127.0.0é:8080",
            "localhosté:8080",
            "",
        ] {
            assert!(!host_allowed(Some(host), 8080), "{host}");
        }
        assert!(!host_allowed(None, 8080));
    }

    #[test]
    fn the_origin_must_be_the_pages_own() {
        assert!(origin_allowed(Some("http://127.0.0.1:5000"), 5000));
        assert!(origin_allowed(Some("http://localhost:5000"), 5000));
        assert!(origin_allowed(Some("http://[::1]:5000"), 5000));
        for origin in [
            "null",
            "https://127.0.0.1:5000",
            "http://127.0.0.1:5001",
            "http://evil.example:5000",
            "http://127.0.0.1:5000/",
            "",
        ] {
            assert!(!origin_allowed(Some(origin), 5000), "{origin}");
        }
        assert!(!origin_allowed(None, 5000));
    }

    #[test]
    fn the_token_is_taken_from_the_query_then_the_cookie() {
        let token = "0123456789abcdef0123456789abcdef";
        assert_eq!(
            token_found(&format!("/?token={token}"), None, token),
            Some(TokenFound::Query)
        );
        assert_eq!(
            token_found("/api/file", Some(&format!("a=b; {COOKIE}={token}")), token),
            Some(TokenFound::Cookie)
        );
        assert_eq!(token_found("/", None, token), None);
        assert_eq!(token_found("/?token=0123", None, token), None);
        assert_eq!(
            token_found("/", Some(&format!("{COOKIE}=x{token}")), token),
            None
        );
        assert_eq!(
            token_found("/", Some(&format!("other_{COOKIE}={token}")), token),
            None
        );
        let set = cookie(token);
        assert!(
            set.contains("HttpOnly") && set.contains("SameSite=Strict"),
            "{set}"
        );
    }

    #[test]
    fn tokens_are_128_random_bits() {
        let (a, b) = (new_token().unwrap(), new_token().unwrap());
        assert_eq!(a.len(), 32);
        assert!(a.bytes().all(|byte| byte.is_ascii_hexdigit()));
        assert_ne!(a, b);
    }

    #[test]
    fn a_body_over_the_cap_is_refused() {
        let body = [b'a'; 100];
        assert!(matches!(
            read_body(Some(100), &mut &body[..], 99),
            Err(BodyError::TooLarge)
        ));
        // Declared smaller (or not at all) than it is.
        assert!(matches!(
            read_body(None, &mut &body[..], 99),
            Err(BodyError::TooLarge)
        ));
        assert_eq!(
            read_body(Some(100), &mut &body[..], 100).unwrap().len(),
            100
        );
        assert!(matches!(
            read_body(None, &mut &[0xff_u8][..], 10),
            Err(BodyError::NotText)
        ));
    }
}
