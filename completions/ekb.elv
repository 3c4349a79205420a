
use builtin;
use str;

set edit:completion:arg-completer[ekb] = {|@words|
    fn spaces {|n|
        builtin:repeat $n ' ' | str:join ''
    }
    fn cand {|text desc|
        edit:complex-candidate $text &display=$text' '(spaces (- 14 (wcswidth $text)))$desc
    }
    var command = 'ekb'
    for word $words[1..-1] {
        if (str:has-prefix $word '-') {
            break
        }
        set command = $command';'$word
    }
    var completions = [
        &'ekb'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
            cand check 'Validate knowledge-base files against every rule'
            cand locations 'A table of all locations'
            cand show 'One location in full'
            cand tour 'The tour in order, as the robot will say it in one language'
            cand diff 'What changed between two knowledge bases, location by location'
            cand export 'The typed model as JSON'
            cand import 'JSON back to a canonical knowledge-base file'
            cand fmt 'Rewrite files in the canonical layout'
            cand fix 'Apply the machine-applicable fixes'
            cand rules 'List the rule catalogue'
            cand explain 'Show one rule''s documentation'
            cand completions 'Print a shell completion script'
            cand man 'Print the man page'
            cand settings 'Print the settings in force for a file, and where each comes from'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'ekb;check'= {
            cand --format 'Output format'
            cand --select 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects'
            cand --extend-select 'Run these rules or categories as well'
            cand --ignore 'Do not run these rules or categories'
            cand --level 'Show only findings at or above this severity (the summary still counts them all)'
            cand --output-file 'Write the report to this file instead of standard output'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --deny-warnings 'Exit 1 on warnings too'
            cand --statistics 'Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix it, the most frequent first'
            cand --exit-zero 'Exit 0 even when there are findings (2 still means ekb could not do its job)'
            cand --add-ignore 'Write a `# ekb: ignore[RULE]` comment above every line with findings, so that the files check clean (to adopt ekb on an existing file); run again, it adds nothing'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;locations'= {
            cand --format 'Output format'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;show'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;tour'= {
            cand --lang 'The language the robot speaks: english, isizulu, kinyarwanda (any case), or en, zu, rw'
            cand --format 'Output format'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;diff'= {
            cand --format 'Output format'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;export'= {
            cand --format 'Output format (JSON is the only one)'
            cand -o 'Write to this file instead of standard output (`-` is standard output)'
            cand --output 'Write to this file instead of standard output (`-` is standard output)'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --allow-errors 'Export even if the file has errors (what the robot would load of it)'
            cand --schema 'Print the JSON Schema of the export instead'
            cand --as-loaded 'Export what the chosen reader loads (`--reader`), field by field, instead of what the file says; exit 1 if that reader would crash on the file'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;import'= {
            cand -o 'Write the knowledge base here (replaced atomically) instead of standard output'
            cand --output 'Write the knowledge base here (replaced atomically) instead of standard output'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;fmt'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --check 'Write nothing; print a diff and exit 1 if a file is not in the canonical layout'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;fix'= {
            cand --dialect 'Migrate to this dialect (`current`: robotLocation becomes robotLocationPose; `seed`: the reverse)'
            cand --select 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects'
            cand --extend-select 'Run these rules or categories as well'
            cand --ignore 'Do not run these rules or categories'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --diff 'Write nothing; print a diff and exit 1 if anything would change'
            cand --unsafe-fixes 'Apply the unsafe fixes too, which guess what was meant: a dash before a number becomes a minus, a decimal comma a point, a file that is not UTF-8 is read as Latin-1'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;rules'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --markdown 'Print the catalogue as a Markdown table (as in the README)'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;explain'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;completions'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;man'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;settings'= {
            cand --select 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects'
            cand --extend-select 'Run these rules or categories as well'
            cand --ignore 'Do not run these rules or categories'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand -v 'Print what is read, as it is read, on standard error'
            cand --verbose 'Print what is read, as it is read, on standard error'
            cand -q 'Print only findings and errors, no summary'
            cand --quiet 'Print only findings and errors, no summary'
            cand --isolated 'Use no settings file: every rule, at its own severity'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'ekb;help'= {
            cand check 'Validate knowledge-base files against every rule'
            cand locations 'A table of all locations'
            cand show 'One location in full'
            cand tour 'The tour in order, as the robot will say it in one language'
            cand diff 'What changed between two knowledge bases, location by location'
            cand export 'The typed model as JSON'
            cand import 'JSON back to a canonical knowledge-base file'
            cand fmt 'Rewrite files in the canonical layout'
            cand fix 'Apply the machine-applicable fixes'
            cand rules 'List the rule catalogue'
            cand explain 'Show one rule''s documentation'
            cand completions 'Print a shell completion script'
            cand man 'Print the man page'
            cand settings 'Print the settings in force for a file, and where each comes from'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'ekb;help;check'= {
        }
        &'ekb;help;locations'= {
        }
        &'ekb;help;show'= {
        }
        &'ekb;help;tour'= {
        }
        &'ekb;help;diff'= {
        }
        &'ekb;help;export'= {
        }
        &'ekb;help;import'= {
        }
        &'ekb;help;fmt'= {
        }
        &'ekb;help;fix'= {
        }
        &'ekb;help;rules'= {
        }
        &'ekb;help;explain'= {
        }
        &'ekb;help;completions'= {
        }
        &'ekb;help;man'= {
        }
        &'ekb;help;settings'= {
        }
        &'ekb;help;help'= {
        }
    ]
    $completions[$command]
}
