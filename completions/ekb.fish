# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_ekb_global_optspecs
    string join \n config= color= v/verbose reader= q/quiet settings= isolated h/help V/version
end

function __fish_ekb_needs_command
    # Figure out if the current invocation already has a command.
    set -l cmd (commandline -opc)
    set -e cmd[1]
    argparse -s (__fish_ekb_global_optspecs) -- $cmd 2>/dev/null
    or return
    if set -q argv[1]
        # Also print the command, so this can be used to figure out what it is.
        echo $argv[1]
        return 1
    end
    return 0
end

function __fish_ekb_using_subcommand
    set -l cmd (__fish_ekb_needs_command)
    test -z "$cmd"
    and return 1
    contains -- $cmd[1] $argv
end

complete -c ekb -n "__fish_ekb_needs_command" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_needs_command" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_needs_command" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_needs_command" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_needs_command" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_needs_command" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_needs_command" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_needs_command" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_needs_command" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "check" -d 'Validate knowledge-base files against every rule'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "locations" -d 'A table of all locations'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "show" -d 'One location in full'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "tour" -d 'The tour in order, as the robot will say it in one language'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "diff" -d 'What changed between two knowledge bases, location by location'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "export" -d 'The typed model as JSON'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "import" -d 'JSON back to a canonical knowledge-base file'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "fmt" -d 'Rewrite files in the canonical layout'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "fix" -d 'Apply the machine-applicable fixes'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "rules" -d 'List the rule catalogue'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "explain" -d 'Show one rule\'s documentation'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "completions" -d 'Print a shell completion script'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "man" -d 'Print the man page'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "map" -d 'Draw the tour on the lab map, as SVG or PNG'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "report" -d 'Write one HTML page to review: the map, the tour\'s messages, the findings'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "mission" -d 'The behaviour-tree mission with both knowledge bases: check, tree, walk'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "translations" -d 'How far each language is translated, message by message'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "set" -d 'Edit one value in place, losslessly'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "lsp" -d 'Run the language server (LSP, on standard input and output) for editors'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "serve" -d 'Edit the knowledge base in a local web page, checked as you type'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "settings" -d 'Print the settings in force for a file, and where each comes from'
complete -c ekb -n "__fish_ekb_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l format -d 'Output format' -r -f -a "human\t'For people: each finding with the lines around it, underlined, and what to do'
concise\t'One line per finding: `file:line:col: severity[rule] message`'
json\t'One JSON object: every finding, with its fix, and a summary'
github\t'GitHub Actions workflow commands (annotations)'
sarif\t'SARIF 2.1.0, for GitHub code scanning and other SARIF viewers'"
complete -c ekb -n "__fish_ekb_using_subcommand check" -l select -d 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects' -r
complete -c ekb -n "__fish_ekb_using_subcommand check" -l extend-select -d 'Run these rules or categories as well' -r
complete -c ekb -n "__fish_ekb_using_subcommand check" -l ignore -d 'Do not run these rules or categories' -r
complete -c ekb -n "__fish_ekb_using_subcommand check" -l level -d 'Show only findings at or above this severity (the summary still counts them all)' -r -f -a "error\t''
warning\t''
info\t''"
complete -c ekb -n "__fish_ekb_using_subcommand check" -l output-file -d 'Write the report to this file instead of standard output' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand check" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand check" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand check" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand check" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand check" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand check" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand check" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand check" -l deny-warnings -d 'Exit 1 on warnings too'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l statistics -d 'Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix it, the most frequent first'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l show-all -d 'Draw every finding in full: without it, a rule with more than three warnings in a file is one paragraph (its count, its lines, the first message)'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l exit-zero -d 'Exit 0 even when there are findings (2 still means ekb could not do its job)'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l add-ignore -d 'Write a `# ekb: ignore[RULE]` comment above every line with findings, so that the files check clean (to adopt ekb on an existing file); run again, it adds nothing'
complete -c ekb -n "__fish_ekb_using_subcommand check" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand check" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand check" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand check" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand check" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l format -d 'Output format' -r -f -a "table\t'A table that fits the terminal'
json\t'One JSON object: the export\'s locations, with message status and tour positions'
classic\t'The layout of the robot\'s printToScreen() (the document\'s Figure 3), to compare with its log'"
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand locations" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand locations" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand locations" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand locations" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand locations" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand show" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand show" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand show" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand show" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand show" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand show" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand show" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand show" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand show" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l lang -d 'The language the robot speaks: english, isizulu (zulu), kinyarwanda, or an ISO 639 code: en/eng, zu/zul, rw/kin (any case); with --timeline also `all`, side by side' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''
all\t''"
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l format -d 'Output format' -r -f -a "text\t'The tour as a script to read'
json\t'One JSON object'"
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l timeline -d 'The tour in time: each leg driven (metres, seconds, the turn; with the map, as the robot\'s planner drives it) and the seconds each message takes to say, and the totals'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand tour" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l format -d 'Output format' -r -f -a "human\t'What changed, for people'
json\t'One JSON object'"
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand diff" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand diff" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand diff" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand diff" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand diff" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand export" -l format -d 'Output format' -r -f -a "json\t'The JSON of SPEC §5'
po\t'gettext PO of one language (--lang), for translators\' tools (SPEC §8)'
pot\t'gettext PO template: every English message, no translation'"
complete -c ekb -n "__fish_ekb_using_subcommand export" -l lang -d 'With --format po: the language to translate into: isizulu (zulu), kinyarwanda, or zu/zul, rw/kin (any case)' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''"
complete -c ekb -n "__fish_ekb_using_subcommand export" -s o -l output -d 'Write to this file instead of standard output (`-` is standard output)' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand export" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand export" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand export" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand export" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand export" -l allow-errors -d 'Export even if the file has errors (what the robot would load of it)'
complete -c ekb -n "__fish_ekb_using_subcommand export" -l schema -d 'Print the JSON Schema of the export instead'
complete -c ekb -n "__fish_ekb_using_subcommand export" -l as-loaded -d 'Export what the chosen reader loads (`--reader`), field by field, instead of what the file says; exit 1 if that reader would crash on the file'
complete -c ekb -n "__fish_ekb_using_subcommand export" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand export" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand export" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand export" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand export" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand import" -s o -l output -d 'Write the knowledge base here (replaced atomically) instead of standard output' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand import" -l po -d 'Import the translations of this PO file into FILE, in place: only those messages change' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand import" -l lang -d 'With --po: the PO file\'s language, if its header has no `Language:` (zu, rw, …)' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''"
complete -c ekb -n "__fish_ekb_using_subcommand import" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand import" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand import" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand import" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand import" -l accept-stale -d 'With --po: import entries made for an English text that has changed since'
complete -c ekb -n "__fish_ekb_using_subcommand import" -l force -d 'With --po: import translations the robot\'s reader would misread, too'
complete -c ekb -n "__fish_ekb_using_subcommand import" -l diff -d 'With --po: write nothing; print the changes as a diff'
complete -c ekb -n "__fish_ekb_using_subcommand import" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand import" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand import" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand import" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand import" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l check -d 'Write nothing; print a diff and exit 1 if a file is not in the canonical layout'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand fmt" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l dialect -d 'Migrate to this dialect (`current`: robotLocation becomes robotLocationPose; `seed`: the reverse)' -r -f -a "seed\t'The document\'s dialect (v1.1): `robotLocation`'
current\t'The robot\'s current dialect: `robotLocationPose`, `culturalKnowledge`, `gestureArm`'"
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l select -d 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects' -r
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l extend-select -d 'Run these rules or categories as well' -r
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l ignore -d 'Do not run these rules or categories' -r
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l diff -d 'Write nothing; print a diff and exit 1 if anything would change'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l unsafe-fixes -d 'Apply the unsafe fixes too, which guess what was meant: a dash before a number becomes a minus, a decimal comma a point, a file that is not UTF-8 is read as Latin-1'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand fix" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l markdown -d 'Print the catalogue as a Markdown table (as in docs/rules.md)'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand rules" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand explain" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand explain" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand explain" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand explain" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand explain" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand explain" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand explain" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand explain" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand explain" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand completions" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand completions" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand completions" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand completions" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand completions" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand completions" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand completions" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand completions" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand completions" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand man" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand man" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand man" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand man" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand man" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand man" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand man" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand man" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand man" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand map" -s o -l output -d 'Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on standard output]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand map" -l format -d 'The drawing\'s format [default: from OUT\'s extension, else svg]' -r -f -a "svg\t'Scalable, self-contained, with selectable text'
png\t'A raster image, rendered with resvg'"
complete -c ekb -n "__fish_ekb_using_subcommand map" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand map" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand map" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand map" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand map" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand map" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand map" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand map" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand map" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand map" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand map" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand map" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand report" -s o -l output -d 'Write the page here (`-` is standard output)' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -l po -d 'Mark the translations these translators\' PO files (of `ekb export --format po`) say were made for an English text that has since changed (stale)' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand report" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand report" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand report" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand report" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand report" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand report" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand report" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand report" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -f -a "check" -d 'Check the mission, the culture knowledge base and the environment knowledge base together'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -f -a "tree" -d 'Print the mission\'s trees, with each node\'s parameter and the phrase each SayText says'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -f -a "walk" -d 'A dry run of the mission on the happy path: the steps the robot takes, in order'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and not __fish_seen_subcommand_from check tree walk help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l config-dir -d 'The robot\'s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l mission -d 'The mission (behaviour tree XML) [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l culture-kb -d 'The culture knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l culture-types -d 'The culture knowledge base\'s types file [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l kb -d 'The environment knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l format -d 'Output format' -r -f -a "human\t'For people: each finding with the lines around it, underlined, and what to do'
concise\t'One line per finding: `file:line:col: severity[rule] message`'
json\t'One JSON object: every finding, with its fix, and a summary'
github\t'GitHub Actions workflow commands (annotations)'
sarif\t'SARIF 2.1.0, for GitHub code scanning and other SARIF viewers'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l deny-warnings -d 'Exit 1 on warnings too'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from check" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l config-dir -d 'The robot\'s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l mission -d 'The mission (behaviour tree XML) [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l culture-kb -d 'The culture knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l culture-types -d 'The culture knowledge base\'s types file [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l kb -d 'The environment knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l lang -d 'The language the robot speaks [default: the culture knowledge base\'s phraseLanguage]' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l format -d 'Output format' -r -f -a "text\t'For people'
json\t'One JSON object'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from tree" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l config-dir -d 'The robot\'s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l mission -d 'The mission (behaviour tree XML) [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l culture-kb -d 'The culture knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l culture-types -d 'The culture knowledge base\'s types file [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l kb -d 'The environment knowledge base [default: from the configuration folder]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l lang -d 'The language the robot speaks [default: the culture knowledge base\'s phraseLanguage]' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l format -d 'Output format' -r -f -a "text\t'For people'
json\t'One JSON object'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from walk" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from help" -f -a "check" -d 'Check the mission, the culture knowledge base and the environment knowledge base together'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from help" -f -a "tree" -d 'Print the mission\'s trees, with each node\'s parameter and the phrase each SayText says'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from help" -f -a "walk" -d 'A dry run of the mission on the happy path: the steps the robot takes, in order'
complete -c ekb -n "__fish_ekb_using_subcommand mission; and __fish_seen_subcommand_from help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l lang -d 'Only this language, and what is left in it, in tour order: english, isizulu (zulu), kinyarwanda, or en/eng, zu/zul, rw/kin (any case)' -r -f -a "english\t''
isizulu\t''
kinyarwanda\t''
zulu\t''
ikinyarwanda\t''
en\t''
zu\t''
rw\t''
eng\t''
zul\t''
kin\t''"
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l format -d 'Output format' -r -f -a "human\t'The status of each language and the grid of messages (with --lang: what is left)'
json\t'One JSON object: each file\'s languages and messages'
csv\t'One row per language and file (with --lang: one row per message left)'"
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l fail-under -d 'Exit 1 when a language shown has fewer than PCT percent of its messages translated (for CI)' -r
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand translations" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand translations" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand translations" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand translations" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand translations" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand set" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand set" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand set" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand set" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand set" -l force -d 'Write the value even if the robot\'s reader would misread it'
complete -c ekb -n "__fish_ekb_using_subcommand set" -l diff -d 'Write nothing; print the change as a diff'
complete -c ekb -n "__fish_ekb_using_subcommand set" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand set" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand set" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand set" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand set" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l stdio -d 'Talk over standard input and output: what the server always does (editors\' clients pass this flag)'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand lsp" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l port -d 'The port on 127.0.0.1 (0: a free one, chosen by the system)' -r
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l map-config -d 'The robot\'s mapGenerationConfiguration.ini: check poses against its map and draw on it' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l map-image -d 'A map image instead (PNG: white free, black occupied), with --map-size; the robot\'s radius is taken as 0.3 m' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l map-size -d 'The map image\'s width and height, in metres' -r
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l open -d 'Say to open the page in a browser (this version prints the address on standard error too; it starts no browser)'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand serve" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l select -d 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects' -r
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l extend-select -d 'Run these rules or categories as well' -r
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l ignore -d 'Do not run these rules or categories' -r
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l config -d 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l color -d 'When to use colour (NO_COLOR in the environment means never, unless `always`)' -r -f -a "auto\t''
always\t''
never\t''"
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l reader -d 'The version of the robot\'s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]' -r -f -a "d5.4.2\t'The document\'s class (D5.4.2, appendix A)'
2025-06\t'`main`, June 2025 (still `main` in April 2026)'
2026-02\t'The `bc_service` branch, February 2026'
2026-03\t'The workspace branch, March 2026: reads `gestureArm`'
2026-04\t'"behaviorController v1.1", April 2026: the arm comes from the culture knowledge base'"
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l settings -d 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file\'s folder or above' -r -F
complete -c ekb -n "__fish_ekb_using_subcommand settings" -s v -l verbose -d 'Print what is read, as it is read, on standard error'
complete -c ekb -n "__fish_ekb_using_subcommand settings" -s q -l quiet -d 'Print only findings and errors, no summary'
complete -c ekb -n "__fish_ekb_using_subcommand settings" -l isolated -d 'Use no settings file: every rule, at its own severity'
complete -c ekb -n "__fish_ekb_using_subcommand settings" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c ekb -n "__fish_ekb_using_subcommand settings" -s V -l version -d 'Print version'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "check" -d 'Validate knowledge-base files against every rule'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "locations" -d 'A table of all locations'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "show" -d 'One location in full'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "tour" -d 'The tour in order, as the robot will say it in one language'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "diff" -d 'What changed between two knowledge bases, location by location'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "export" -d 'The typed model as JSON'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "import" -d 'JSON back to a canonical knowledge-base file'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "fmt" -d 'Rewrite files in the canonical layout'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "fix" -d 'Apply the machine-applicable fixes'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "rules" -d 'List the rule catalogue'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "explain" -d 'Show one rule\'s documentation'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "completions" -d 'Print a shell completion script'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "man" -d 'Print the man page'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "map" -d 'Draw the tour on the lab map, as SVG or PNG'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "report" -d 'Write one HTML page to review: the map, the tour\'s messages, the findings'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "mission" -d 'The behaviour-tree mission with both knowledge bases: check, tree, walk'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "translations" -d 'How far each language is translated, message by message'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "set" -d 'Edit one value in place, losslessly'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "lsp" -d 'Run the language server (LSP, on standard input and output) for editors'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "serve" -d 'Edit the knowledge base in a local web page, checked as you type'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "settings" -d 'Print the settings in force for a file, and where each comes from'
complete -c ekb -n "__fish_ekb_using_subcommand help; and not __fish_seen_subcommand_from check locations show tour diff export import fmt fix rules explain completions man map report mission translations set lsp serve settings help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c ekb -n "__fish_ekb_using_subcommand help; and __fish_seen_subcommand_from mission" -f -a "check" -d 'Check the mission, the culture knowledge base and the environment knowledge base together'
complete -c ekb -n "__fish_ekb_using_subcommand help; and __fish_seen_subcommand_from mission" -f -a "tree" -d 'Print the mission\'s trees, with each node\'s parameter and the phrase each SayText says'
complete -c ekb -n "__fish_ekb_using_subcommand help; and __fish_seen_subcommand_from mission" -f -a "walk" -d 'A dry run of the mission on the happy path: the steps the robot takes, in order'
