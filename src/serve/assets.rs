//! The page of `ekb serve`: HTML, JavaScript and CSS written by hand, no build step and no
//! framework, compiled into the program (nothing is fetched from the network). The page
//! builds its sections from `/api/file` with `textContent` only: no text of the file is
//! ever parsed as HTML.

pub const INDEX_HTML: &str = include_str!("assets/index.html");
pub const APP_JS: &str = include_str!("assets/app.js");
pub const APP_CSS: &str = include_str!("assets/app.css");
