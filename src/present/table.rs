//! Terminal tables: one look for every command that prints one.

use comfy_table::{presets, ContentArrangement, Table};

/// A table that fits the terminal: comfy-table measures it when standard output is one;
/// `COLUMNS` sets the width otherwise (and wins, as for other tools).
pub fn new(header: &[&str]) -> Table {
    let mut table = Table::new();
    table
        .load_preset(presets::UTF8_FULL_CONDENSED)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_header(header.to_vec());
    if let Some(width) = std::env::var("COLUMNS")
        .ok()
        .and_then(|value| value.trim().parse::<u16>().ok())
        .filter(|&width| width >= 20)
    {
        table.set_width(width);
    }
    table
}
