//! `ekb man`: one man page for the whole tool, generated from the same CLI definition as
//! `--help`: the global options, every subcommand with its own, and what `--help` does not
//! tell: the exit status, the environment and the configuration file.

use std::io::{self, Write};

use clap_mangen::Man;

use super::{CommandResult, Exit};
use crate::config;
use crate::robot::Reader;

#[derive(Debug, clap::Args)]
pub struct Args {}

/// Prints the page of `cli`, the whole command line.
pub fn run(_args: &Args, cli: clap::Command) -> CommandResult {
    let mut stdout = std::io::stdout().lock();
    stdout.write_all(page(cli)?.as_bytes())?;
    Ok(Exit::Clean)
}

/// The page, in roff. The subcommands are sections of it, not pages of their own (which
/// clap_mangen would name, as `ekb-check(1)`, without writing them).
pub fn page(cli: clap::Command) -> io::Result<String> {
    let man = Man::new(cli.clone());
    let mut page = rendered(|out| man.render_title(out))?;
    page += &rendered(|out| man.render_name_section(out))?;
    page += &rendered(|out| man.render_synopsis_section(out))?;
    page += &rendered(|out| man.render_description_section(out))?;
    page += &rendered(|out| man.render_options_section(out))?;
    page += ".SH COMMANDS\n";
    for command in cli.get_subcommands() {
        page += &command_section(command)?;
    }
    page += EXAMPLES;
    page += EXIT_STATUS;
    page += &environment();
    page += &files();
    page += &rendered(|out| man.render_version_section(out))?;
    Ok(preamble(cli)? + &page)
}

/// `ekb check` as a subsection: what it does, its synopsis and its own options (the global
/// ones are in OPTIONS).
fn command_section(command: &clap::Command) -> io::Result<String> {
    let name = format!("ekb {}", command.get_name());
    let man = Man::new(
        command
            .clone()
            .bin_name(&name)
            // `-h` is on every command: told once, in OPTIONS.
            .disable_help_flag(true),
    );
    let mut section = format!(".SS \"{name}\"\n");
    section += &without_headings(&rendered(|out| man.render_description_section(out))?);
    section += ".PP\n";
    section += &without_headings(&rendered(|out| man.render_synopsis_section(out))?);
    section += &without_headings(&rendered(|out| man.render_options_section(out))?);
    Ok(section)
}

/// What one of clap_mangen's renderers writes, without the preamble each one starts with.
fn rendered(render: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> io::Result<String> {
    let mut out = Vec::new();
    render(&mut out)?;
    let text = String::from_utf8(out).map_err(io::Error::other)?;
    Ok(text
        .lines()
        .filter(|line| !is_preamble(line))
        .map(|line| format!("{line}\n"))
        .collect())
}

/// The lines that define the `Aq` string (an apostrophe) in clap_mangen's roff: written once,
/// at the top of the page.
fn preamble(cli: clap::Command) -> io::Result<String> {
    let mut out = Vec::new();
    Man::new(cli).render_title(&mut out)?;
    let text = String::from_utf8(out).map_err(io::Error::other)?;
    Ok(text
        .lines()
        .filter(|line| is_preamble(line))
        .map(|line| format!("{line}\n"))
        .collect())
}

fn is_preamble(line: &str) -> bool {
    line.starts_with(".ie \\n(.g .ds Aq") || line.starts_with(".el .ds Aq")
}

/// A section's body without its `.SH` heading, to become part of a subsection.
fn without_headings(section: &str) -> String {
    section
        .lines()
        .filter(|line| !line.starts_with(".SH "))
        .map(|line| format!("{line}\n"))
        .collect()
}

/// The first hour's commands, in the order a content editor, a translator and a robot
/// engineer meet them (each is run by a test).
const EXAMPLES: &str = r#".SH EXAMPLES
.TP
.B ekb check data/environmentKnowledgeBaseInput.dat
What the robot would load, and what is wrong: errors first, each after what causes it.
.TP
.B ekb check \-\-show\-all \-\-select untranslated\-message FILE
Every finding of one rule, where the report groups many of them into one paragraph.
.TP
.B ekb fix \-\-diff FILE
What \fBekb fix\fR would change, without writing; \fBekb fix FILE\fR then fixes it in place.
.TP
.B ekb explain key\-case
One rule: what it does, why it matters, an example.
.TP
.B ekb tour \-\-lang rw FILE
The tour as the robot says it, in Kinyarwanda; \fBekb tour \-\-timeline \-\-lang all FILE\fR how long each leg and each message takes, in each language.
.TP
.B ekb export \-\-format po \-\-lang zu \-o zu.po FILE
A PO file for translators; \fBekb import \-\-po zu.po FILE\fR brings their isiZulu back, changing only those lines.
.TP
.B ekb set 4 preGestureMessageIsiZulu \(dqLe yiRoomba\(dq FILE
One value, changed in place.
.TP
.B ekb map \-o tour.png FILE
The tour drawn on the lab map; \fBekb report \-o report.html FILE\fR puts the map, the messages and the findings on one page.
.TP
.B ekb mission check \-\-config\-dir config
The behaviour tree and both knowledge bases, as the robot's configuration folder names them.
"#;

const EXIT_STATUS: &str = r#".SH "EXIT STATUS"
.TP
.B 0
Clean: no errors (warnings are allowed unless \fB\-\-deny\-warnings\fR is given), no difference, nothing to change.
.TP
.B 1
Errors found, differences found, or something would change (\fBfmt \-\-check\fR, \fBfix \-\-diff\fR, \fBimport \-\-po \-\-diff\fR); also \fBimport\fR and \fBfix\fR when the file they write still has errors.
.TP
.B 2
\fBekb\fR could not do its job: a usage error, an unreadable file, a bad configuration, a file it refuses to rewrite. One line on standard error says why.
"#;

fn environment() -> String {
    format!(
        r#".SH ENVIRONMENT
.TP
.B {}
The configuration file, when \fB\-\-config\fR is not given.
.TP
.B NO_COLOR
When set and not empty, no colour, unless \fB\-\-color always\fR is given.
"#,
        config::ENV_VAR
    )
}

fn files() -> String {
    let readers: Vec<String> = Reader::ALL
        .iter()
        .map(|reader| format!("\\fB{}\\fR", reader.name().replace('-', "\\-")))
        .collect();
    format!(
        r#".SH FILES
.TP
.I {}
The configuration, under the current folder, used when neither \fB\-\-config\fR nor \fB{}\fR names one; with none, give \fBekb\fR the \fIFILE\fR to work on. It is the robot's own file: standard INI (\fIkey\fR = \fIvalue\fR) or the robot's whitespace form (\fIkey\fR \fIvalue\fR), with \fB;\fR or \fB#\fR comments, also after a value. A key \fBekb\fR does not know is ignored with a warning. The keys:
.RS
.TP
.B knowledgeBase
The knowledge base that a command given no \fIFILE\fR works on. A relative name is resolved in the \fIdata/\fR folder beside the configuration's folder, as on the robot.
.TP
.B verboseMode
\fBtrue\fR or \fBfalse\fR: print what is read, as it is read, on standard error (as \fB\-v\fR does).
.TP
.B dialect
\fBseed\fR, \fBcurrent\fR or \fBauto\fR (the default, which detects it per file): with one pinned, keys of the other dialect are \fBlegacy\-key\fR errors.
.TP
.B reader
The version of the robot's reader that the file is checked against: {}.
.RE
"#,
        config::DEFAULT_PATH.replace('-', "\\-"),
        config::ENV_VAR,
        readers.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_configuration_key_is_documented() {
        use clap::CommandFactory;
        let page = page(crate::cli::Cli::command()).unwrap();
        for key in config::KEYS {
            assert!(page.contains(&format!(".B {key}\n")), "{key}");
        }
    }
}
