
using namespace System.Management.Automation
using namespace System.Management.Automation.Language

Register-ArgumentCompleter -Native -CommandName 'ekb' -ScriptBlock {
    param($wordToComplete, $commandAst, $cursorPosition)

    $commandElements = $commandAst.CommandElements
    $command = @(
        'ekb'
        for ($i = 1; $i -lt $commandElements.Count; $i++) {
            $element = $commandElements[$i]
            if ($element -isnot [StringConstantExpressionAst] -or
                $element.StringConstantType -ne [StringConstantType]::BareWord -or
                $element.Value.StartsWith('-') -or
                $element.Value -eq $wordToComplete) {
                break
        }
        $element.Value
    }) -join ';'

    $completions = @(switch ($command) {
        'ekb' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Validate knowledge-base files against every rule')
            [CompletionResult]::new('locations', 'locations', [CompletionResultType]::ParameterValue, 'A table of all locations')
            [CompletionResult]::new('show', 'show', [CompletionResultType]::ParameterValue, 'One location in full')
            [CompletionResult]::new('tour', 'tour', [CompletionResultType]::ParameterValue, 'The tour in order, as the robot will say it in one language')
            [CompletionResult]::new('diff', 'diff', [CompletionResultType]::ParameterValue, 'What changed between two knowledge bases, location by location')
            [CompletionResult]::new('export', 'export', [CompletionResultType]::ParameterValue, 'The typed model as JSON')
            [CompletionResult]::new('import', 'import', [CompletionResultType]::ParameterValue, 'JSON back to a canonical knowledge-base file')
            [CompletionResult]::new('fmt', 'fmt', [CompletionResultType]::ParameterValue, 'Rewrite files in the canonical layout')
            [CompletionResult]::new('fix', 'fix', [CompletionResultType]::ParameterValue, 'Apply the machine-applicable fixes')
            [CompletionResult]::new('rules', 'rules', [CompletionResultType]::ParameterValue, 'List the rule catalogue')
            [CompletionResult]::new('explain', 'explain', [CompletionResultType]::ParameterValue, 'Show one rule''s documentation')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the man page')
            [CompletionResult]::new('map', 'map', [CompletionResultType]::ParameterValue, 'Draw the tour on the lab map, as SVG or PNG')
            [CompletionResult]::new('report', 'report', [CompletionResultType]::ParameterValue, 'Write one HTML page to review: the map, the tour''s messages, the findings')
            [CompletionResult]::new('mission', 'mission', [CompletionResultType]::ParameterValue, 'The behaviour-tree mission with both knowledge bases: check, tree, walk')
            [CompletionResult]::new('translations', 'translations', [CompletionResultType]::ParameterValue, 'How far each language is translated, message by message')
            [CompletionResult]::new('set', 'set', [CompletionResultType]::ParameterValue, 'Edit one value in place, losslessly')
            [CompletionResult]::new('lsp', 'lsp', [CompletionResultType]::ParameterValue, 'Run the language server (LSP, on standard input and output) for editors')
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Edit the knowledge base in a local web page, checked as you type')
            [CompletionResult]::new('settings', 'settings', [CompletionResultType]::ParameterValue, 'Print the settings in force for a file, and where each comes from')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'ekb;check' {
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--select', '--select', [CompletionResultType]::ParameterName, 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects')
            [CompletionResult]::new('--extend-select', '--extend-select', [CompletionResultType]::ParameterName, 'Run these rules or categories as well')
            [CompletionResult]::new('--ignore', '--ignore', [CompletionResultType]::ParameterName, 'Do not run these rules or categories')
            [CompletionResult]::new('--level', '--level', [CompletionResultType]::ParameterName, 'Show only findings at or above this severity (the summary still counts them all)')
            [CompletionResult]::new('--output-file', '--output-file', [CompletionResultType]::ParameterName, 'Write the report to this file instead of standard output')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--deny-warnings', '--deny-warnings', [CompletionResultType]::ParameterName, 'Exit 1 on warnings too')
            [CompletionResult]::new('--statistics', '--statistics', [CompletionResultType]::ParameterName, 'Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix it, the most frequent first')
            [CompletionResult]::new('--show-all', '--show-all', [CompletionResultType]::ParameterName, 'Draw every finding in full: without it, a rule with more than three warnings in a file is one paragraph (its count, its lines, the first message)')
            [CompletionResult]::new('--exit-zero', '--exit-zero', [CompletionResultType]::ParameterName, 'Exit 0 even when there are findings (2 still means ekb could not do its job)')
            [CompletionResult]::new('--add-ignore', '--add-ignore', [CompletionResultType]::ParameterName, 'Write a `# ekb: ignore[RULE]` comment above every line with findings, so that the files check clean (to adopt ekb on an existing file); run again, it adds nothing')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;locations' {
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;show' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;tour' {
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language the robot speaks: english, isizulu (zulu), kinyarwanda, or an ISO 639 code: en/eng, zu/zul, rw/kin (any case); with --timeline also `all`, side by side')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--timeline', '--timeline', [CompletionResultType]::ParameterName, 'The tour in time: each leg driven (metres, seconds, the turn; with the map, as the robot''s planner drives it) and the seconds each message takes to say, and the totals')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;diff' {
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;export' {
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'With --format po: the language to translate into: isizulu (zulu), kinyarwanda, or zu/zul, rw/kin (any case)')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write to this file instead of standard output (`-` is standard output)')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write to this file instead of standard output (`-` is standard output)')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--allow-errors', '--allow-errors', [CompletionResultType]::ParameterName, 'Export even if the file has errors (what the robot would load of it)')
            [CompletionResult]::new('--schema', '--schema', [CompletionResultType]::ParameterName, 'Print the JSON Schema of the export instead')
            [CompletionResult]::new('--as-loaded', '--as-loaded', [CompletionResultType]::ParameterName, 'Export what the chosen reader loads (`--reader`), field by field, instead of what the file says; exit 1 if that reader would crash on the file')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;import' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the knowledge base here (replaced atomically) instead of standard output')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the knowledge base here (replaced atomically) instead of standard output')
            [CompletionResult]::new('--po', '--po', [CompletionResultType]::ParameterName, 'Import the translations of this PO file into FILE, in place: only those messages change')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'With --po: the PO file''s language, if its header has no `Language:` (zu, rw, …)')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--accept-stale', '--accept-stale', [CompletionResultType]::ParameterName, 'With --po: import entries made for an English text that has changed since')
            [CompletionResult]::new('--force', '--force', [CompletionResultType]::ParameterName, 'With --po: import translations the robot''s reader would misread, too')
            [CompletionResult]::new('--diff', '--diff', [CompletionResultType]::ParameterName, 'With --po: write nothing; print the changes as a diff')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;fmt' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--check', '--check', [CompletionResultType]::ParameterName, 'Write nothing; print a diff and exit 1 if a file is not in the canonical layout')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;fix' {
            [CompletionResult]::new('--dialect', '--dialect', [CompletionResultType]::ParameterName, 'Migrate to this dialect (`current`: robotLocation becomes robotLocationPose; `seed`: the reverse)')
            [CompletionResult]::new('--select', '--select', [CompletionResultType]::ParameterName, 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects')
            [CompletionResult]::new('--extend-select', '--extend-select', [CompletionResultType]::ParameterName, 'Run these rules or categories as well')
            [CompletionResult]::new('--ignore', '--ignore', [CompletionResultType]::ParameterName, 'Do not run these rules or categories')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--diff', '--diff', [CompletionResultType]::ParameterName, 'Write nothing; print a diff and exit 1 if anything would change')
            [CompletionResult]::new('--unsafe-fixes', '--unsafe-fixes', [CompletionResultType]::ParameterName, 'Apply the unsafe fixes too, which guess what was meant: a dash before a number becomes a minus, a decimal comma a point, a file that is not UTF-8 is read as Latin-1')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;rules' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--markdown', '--markdown', [CompletionResultType]::ParameterName, 'Print the catalogue as a Markdown table (as in docs/rules.md)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;explain' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;completions' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;man' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;map' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on standard output]')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on standard output]')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'The drawing''s format [default: from OUT''s extension, else svg]')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;report' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Write the page here (`-` is standard output)')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Write the page here (`-` is standard output)')
            [CompletionResult]::new('--po', '--po', [CompletionResultType]::ParameterName, 'Mark the translations these translators'' PO files (of `ekb export --format po`) say were made for an English text that has since changed (stale)')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;mission' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check the mission, the culture knowledge base and the environment knowledge base together')
            [CompletionResult]::new('tree', 'tree', [CompletionResultType]::ParameterValue, 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says')
            [CompletionResult]::new('walk', 'walk', [CompletionResultType]::ParameterValue, 'A dry run of the mission on the happy path: the steps the robot takes, in order')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'ekb;mission;check' {
            [CompletionResult]::new('--config-dir', '--config-dir', [CompletionResultType]::ParameterName, 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]')
            [CompletionResult]::new('--mission', '--mission', [CompletionResultType]::ParameterName, 'The mission (behaviour tree XML) [default: from the configuration folder]')
            [CompletionResult]::new('--culture-kb', '--culture-kb', [CompletionResultType]::ParameterName, 'The culture knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--culture-types', '--culture-types', [CompletionResultType]::ParameterName, 'The culture knowledge base''s types file [default: from the configuration folder]')
            [CompletionResult]::new('--kb', '--kb', [CompletionResultType]::ParameterName, 'The environment knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--deny-warnings', '--deny-warnings', [CompletionResultType]::ParameterName, 'Exit 1 on warnings too')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;mission;tree' {
            [CompletionResult]::new('--config-dir', '--config-dir', [CompletionResultType]::ParameterName, 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]')
            [CompletionResult]::new('--mission', '--mission', [CompletionResultType]::ParameterName, 'The mission (behaviour tree XML) [default: from the configuration folder]')
            [CompletionResult]::new('--culture-kb', '--culture-kb', [CompletionResultType]::ParameterName, 'The culture knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--culture-types', '--culture-types', [CompletionResultType]::ParameterName, 'The culture knowledge base''s types file [default: from the configuration folder]')
            [CompletionResult]::new('--kb', '--kb', [CompletionResultType]::ParameterName, 'The environment knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language the robot speaks [default: the culture knowledge base''s phraseLanguage]')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;mission;walk' {
            [CompletionResult]::new('--config-dir', '--config-dir', [CompletionResultType]::ParameterName, 'The robot''s configuration folder: its behaviorControllerConfiguration.ini, cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]')
            [CompletionResult]::new('--mission', '--mission', [CompletionResultType]::ParameterName, 'The mission (behaviour tree XML) [default: from the configuration folder]')
            [CompletionResult]::new('--culture-kb', '--culture-kb', [CompletionResultType]::ParameterName, 'The culture knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--culture-types', '--culture-types', [CompletionResultType]::ParameterName, 'The culture knowledge base''s types file [default: from the configuration folder]')
            [CompletionResult]::new('--kb', '--kb', [CompletionResultType]::ParameterName, 'The environment knowledge base [default: from the configuration folder]')
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'The language the robot speaks [default: the culture knowledge base''s phraseLanguage]')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;mission;help' {
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check the mission, the culture knowledge base and the environment knowledge base together')
            [CompletionResult]::new('tree', 'tree', [CompletionResultType]::ParameterValue, 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says')
            [CompletionResult]::new('walk', 'walk', [CompletionResultType]::ParameterValue, 'A dry run of the mission on the happy path: the steps the robot takes, in order')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'ekb;mission;help;check' {
            break
        }
        'ekb;mission;help;tree' {
            break
        }
        'ekb;mission;help;walk' {
            break
        }
        'ekb;mission;help;help' {
            break
        }
        'ekb;translations' {
            [CompletionResult]::new('--lang', '--lang', [CompletionResultType]::ParameterName, 'Only this language, and what is left in it, in tour order: english, isizulu (zulu), kinyarwanda, or en/eng, zu/zul, rw/kin (any case)')
            [CompletionResult]::new('--format', '--format', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--fail-under', '--fail-under', [CompletionResultType]::ParameterName, 'Exit 1 when a language shown has fewer than PCT percent of its messages translated (for CI)')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;set' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--force', '--force', [CompletionResultType]::ParameterName, 'Write the value even if the robot''s reader would misread it')
            [CompletionResult]::new('--diff', '--diff', [CompletionResultType]::ParameterName, 'Write nothing; print the change as a diff')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;lsp' {
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--stdio', '--stdio', [CompletionResultType]::ParameterName, 'Talk over standard input and output: what the server always does (editors'' clients pass this flag)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;serve' {
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'The port on 127.0.0.1 (0: a free one, chosen by the system)')
            [CompletionResult]::new('--map-config', '--map-config', [CompletionResultType]::ParameterName, 'The robot''s mapGenerationConfiguration.ini: check poses against its map and draw on it')
            [CompletionResult]::new('--map-image', '--map-image', [CompletionResultType]::ParameterName, 'A map image instead (PNG: white free, black occupied), with --map-size; the robot''s radius is taken as 0.3 m')
            [CompletionResult]::new('--map-size', '--map-size', [CompletionResultType]::ParameterName, 'The map image''s width and height, in metres')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('--open', '--open', [CompletionResultType]::ParameterName, 'Say to open the page in a browser (this version prints the address on standard error too; it starts no browser)')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;settings' {
            [CompletionResult]::new('--select', '--select', [CompletionResultType]::ParameterName, 'Run only these rules or categories (comma-separated), instead of those ekb.toml selects')
            [CompletionResult]::new('--extend-select', '--extend-select', [CompletionResultType]::ParameterName, 'Run these rules or categories as well')
            [CompletionResult]::new('--ignore', '--ignore', [CompletionResultType]::ParameterName, 'Do not run these rules or categories')
            [CompletionResult]::new('--config', '--config', [CompletionResultType]::ParameterName, 'Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]')
            [CompletionResult]::new('--color', '--color', [CompletionResultType]::ParameterName, 'When to use colour (NO_COLOR in the environment means never, unless `always`)')
            [CompletionResult]::new('--reader', '--reader', [CompletionResultType]::ParameterName, 'The version of the robot''s reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]')
            [CompletionResult]::new('--settings', '--settings', [CompletionResultType]::ParameterName, 'Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file''s folder or above')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print what is read, as it is read, on standard error')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'Print only findings and errors, no summary')
            [CompletionResult]::new('--isolated', '--isolated', [CompletionResultType]::ParameterName, 'Use no settings file: every rule, at its own severity')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'ekb;help' {
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Validate knowledge-base files against every rule')
            [CompletionResult]::new('locations', 'locations', [CompletionResultType]::ParameterValue, 'A table of all locations')
            [CompletionResult]::new('show', 'show', [CompletionResultType]::ParameterValue, 'One location in full')
            [CompletionResult]::new('tour', 'tour', [CompletionResultType]::ParameterValue, 'The tour in order, as the robot will say it in one language')
            [CompletionResult]::new('diff', 'diff', [CompletionResultType]::ParameterValue, 'What changed between two knowledge bases, location by location')
            [CompletionResult]::new('export', 'export', [CompletionResultType]::ParameterValue, 'The typed model as JSON')
            [CompletionResult]::new('import', 'import', [CompletionResultType]::ParameterValue, 'JSON back to a canonical knowledge-base file')
            [CompletionResult]::new('fmt', 'fmt', [CompletionResultType]::ParameterValue, 'Rewrite files in the canonical layout')
            [CompletionResult]::new('fix', 'fix', [CompletionResultType]::ParameterValue, 'Apply the machine-applicable fixes')
            [CompletionResult]::new('rules', 'rules', [CompletionResultType]::ParameterValue, 'List the rule catalogue')
            [CompletionResult]::new('explain', 'explain', [CompletionResultType]::ParameterValue, 'Show one rule''s documentation')
            [CompletionResult]::new('completions', 'completions', [CompletionResultType]::ParameterValue, 'Print a shell completion script')
            [CompletionResult]::new('man', 'man', [CompletionResultType]::ParameterValue, 'Print the man page')
            [CompletionResult]::new('map', 'map', [CompletionResultType]::ParameterValue, 'Draw the tour on the lab map, as SVG or PNG')
            [CompletionResult]::new('report', 'report', [CompletionResultType]::ParameterValue, 'Write one HTML page to review: the map, the tour''s messages, the findings')
            [CompletionResult]::new('mission', 'mission', [CompletionResultType]::ParameterValue, 'The behaviour-tree mission with both knowledge bases: check, tree, walk')
            [CompletionResult]::new('translations', 'translations', [CompletionResultType]::ParameterValue, 'How far each language is translated, message by message')
            [CompletionResult]::new('set', 'set', [CompletionResultType]::ParameterValue, 'Edit one value in place, losslessly')
            [CompletionResult]::new('lsp', 'lsp', [CompletionResultType]::ParameterValue, 'Run the language server (LSP, on standard input and output) for editors')
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Edit the knowledge base in a local web page, checked as you type')
            [CompletionResult]::new('settings', 'settings', [CompletionResultType]::ParameterValue, 'Print the settings in force for a file, and where each comes from')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'ekb;help;check' {
            break
        }
        'ekb;help;locations' {
            break
        }
        'ekb;help;show' {
            break
        }
        'ekb;help;tour' {
            break
        }
        'ekb;help;diff' {
            break
        }
        'ekb;help;export' {
            break
        }
        'ekb;help;import' {
            break
        }
        'ekb;help;fmt' {
            break
        }
        'ekb;help;fix' {
            break
        }
        'ekb;help;rules' {
            break
        }
        'ekb;help;explain' {
            break
        }
        'ekb;help;completions' {
            break
        }
        'ekb;help;man' {
            break
        }
        'ekb;help;map' {
            break
        }
        'ekb;help;report' {
            break
        }
        'ekb;help;mission' {
            [CompletionResult]::new('check', 'check', [CompletionResultType]::ParameterValue, 'Check the mission, the culture knowledge base and the environment knowledge base together')
            [CompletionResult]::new('tree', 'tree', [CompletionResultType]::ParameterValue, 'Print the mission''s trees, with each node''s parameter and the phrase each SayText says')
            [CompletionResult]::new('walk', 'walk', [CompletionResultType]::ParameterValue, 'A dry run of the mission on the happy path: the steps the robot takes, in order')
            break
        }
        'ekb;help;mission;check' {
            break
        }
        'ekb;help;mission;tree' {
            break
        }
        'ekb;help;mission;walk' {
            break
        }
        'ekb;help;translations' {
            break
        }
        'ekb;help;set' {
            break
        }
        'ekb;help;lsp' {
            break
        }
        'ekb;help;serve' {
            break
        }
        'ekb;help;settings' {
            break
        }
        'ekb;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
