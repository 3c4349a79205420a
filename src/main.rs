fn main() -> std::process::ExitCode {
    ekb::cli::main()
}
