//! How a knowledge base is named to people, where the core needs it too: the languages'
//! names and codes ([`language`]). The tables and fields are the command line's
//! (`ekb::present`).

pub mod language;
