
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
            cand map 'Draw the tour on the lab map, as SVG or PNG'
            cand report 'Write one HTML page to review: the map, the tour''s messages, the findings'
            cand mission 'The behaviour-tree mission with both knowledge bases: check, tree, walk'
            cand translations 'How far each language is translated, message by message'
            cand set 'Edit one value in place, losslessly'
            cand lsp 'Run the language server (LSP, on standard input and output) for editors'
            cand serve 'Edit the knowledge base in a local web page, checked as you type'
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
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --deny-warnings 'Exit 1 on warnings too'
            cand --statistics 'Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix it, the most frequent first'
            cand --show-all 'Draw every finding in full: without it, a rule with more than three warnings in a file is one paragraph (its count, its lines, the first message)'
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
            cand --lang 'The language the robot speaks: english, isizulu (zulu), kinyarwanda, or an ISO 639 code: en/eng, zu/zul, rw/kin (any case); with --timeline also `all`, side by side'
            cand --format 'Output format'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --timeline 'The tour in time: each leg driven (metres, seconds, the turn; with the map, as the robot''s planner drives it) and the seconds each message takes to say, and the totals'
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
            cand --format 'Output format'
            cand --lang 'With --format po: the language to translate into: isizulu (zulu), kinyarwanda, or zu/zul, rw/kin (any case)'
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
            cand --po 'Import the translations of this PO file into FILE, in place: only those messages change'
            cand --lang 'With --po: the PO file''s language, if its header has no `Language:` (zu, rw, …)'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --accept-stale 'With --po: import entries made for an English text that has changed since'
            cand --force 'With --po: import translations the robot''s reader would misread, too'
            cand --diff 'With --po: write nothing; print the changes as a diff'
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
            cand --markdown 'Print the catalogue as a Markdown table (as in docs/rules.md)'
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
        &'ekb;map'= {
            cand -o 'Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on standard output]'
            cand --output 'Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on standard output]'
            cand --format 'The drawing''s format [default: from OUT''s extension, else svg]'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
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
        &'ekb;report'= {
            cand -o 'Write the page here (`-` is standard output)'
            cand --output 'Write the page here (`-` is standard output)'
            cand --po 'Mark the translations these translators'' PO files (of `ekb export --format po`) say were made for an English text that has since changed (stale)'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
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
        &'ekb;mission'= {
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
            cand check 'Check the mission, the culture knowledge base and the environment knowledge base together'
            cand tree 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says'
            cand walk 'A dry run of the mission on the happy path: the steps the robot takes, in order'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'ekb;mission;check'= {
            cand --config-dir 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]'
            cand --mission 'The mission (behaviour tree XML) [default: from the configuration folder]'
            cand --culture-kb 'The culture knowledge base [default: from the configuration folder]'
            cand --culture-types 'The culture knowledge base''s types file [default: from the configuration folder]'
            cand --kb 'The environment knowledge base [default: from the configuration folder]'
            cand --format 'Output format'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --deny-warnings 'Exit 1 on warnings too'
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
        &'ekb;mission;tree'= {
            cand --config-dir 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]'
            cand --mission 'The mission (behaviour tree XML) [default: from the configuration folder]'
            cand --culture-kb 'The culture knowledge base [default: from the configuration folder]'
            cand --culture-types 'The culture knowledge base''s types file [default: from the configuration folder]'
            cand --kb 'The environment knowledge base [default: from the configuration folder]'
            cand --lang 'The language the robot speaks [default: the culture knowledge base''s phraseLanguage]'
            cand --format 'Output format'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
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
        &'ekb;mission;walk'= {
            cand --config-dir 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]'
            cand --mission 'The mission (behaviour tree XML) [default: from the configuration folder]'
            cand --culture-kb 'The culture knowledge base [default: from the configuration folder]'
            cand --culture-types 'The culture knowledge base''s types file [default: from the configuration folder]'
            cand --kb 'The environment knowledge base [default: from the configuration folder]'
            cand --lang 'The language the robot speaks [default: the culture knowledge base''s phraseLanguage]'
            cand --format 'Output format'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
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
        &'ekb;mission;help'= {
            cand check 'Check the mission, the culture knowledge base and the environment knowledge base together'
            cand tree 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says'
            cand walk 'A dry run of the mission on the happy path: the steps the robot takes, in order'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'ekb;mission;help;check'= {
        }
        &'ekb;mission;help;tree'= {
        }
        &'ekb;mission;help;walk'= {
        }
        &'ekb;mission;help;help'= {
        }
        &'ekb;translations'= {
            cand --lang 'Only this language, and what is left in it, in tour order: english, isizulu (zulu), kinyarwanda, or en/eng, zu/zul, rw/kin (any case)'
            cand --format 'Output format'
            cand --fail-under 'Exit 1 when a language shown has fewer than PCT percent of its messages translated (for CI)'
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
        &'ekb;set'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --force 'Write the value even if the robot''s reader would misread it'
            cand --diff 'Write nothing; print the change as a diff'
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
        &'ekb;lsp'= {
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --stdio 'Talk over standard input and output: what the server always does (editors'' clients pass this flag)'
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
        &'ekb;serve'= {
            cand --port 'The port on 127.0.0.1 (0: a free one, chosen by the system)'
            cand --map-config 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it'
            cand --map-image 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m'
            cand --map-size 'The map image''s width and height, in metres'
            cand --config 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]'
            cand --color 'When to use colour (NO_COLOR in the environment means never, unless `always`)'
            cand --reader 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]'
            cand --settings 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above'
            cand --open 'Say to open the page in a browser (this version prints the address on standard error too; it starts no browser)'
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
            cand map 'Draw the tour on the lab map, as SVG or PNG'
            cand report 'Write one HTML page to review: the map, the tour''s messages, the findings'
            cand mission 'The behaviour-tree mission with both knowledge bases: check, tree, walk'
            cand translations 'How far each language is translated, message by message'
            cand set 'Edit one value in place, losslessly'
            cand lsp 'Run the language server (LSP, on standard input and output) for editors'
            cand serve 'Edit the knowledge base in a local web page, checked as you type'
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
        &'ekb;help;map'= {
        }
        &'ekb;help;report'= {
        }
        &'ekb;help;mission'= {
            cand check 'Check the mission, the culture knowledge base and the environment knowledge base together'
            cand tree 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says'
            cand walk 'A dry run of the mission on the happy path: the steps the robot takes, in order'
        }
        &'ekb;help;mission;check'= {
        }
        &'ekb;help;mission;tree'= {
        }
        &'ekb;help;mission;walk'= {
        }
        &'ekb;help;translations'= {
        }
        &'ekb;help;set'= {
        }
        &'ekb;help;lsp'= {
        }
        &'ekb;help;serve'= {
        }
        &'ekb;help;settings'= {
        }
        &'ekb;help;help'= {
        }
    ]
    $completions[$command]
}
