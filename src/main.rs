use clap::Parser;

fn main() -> std::process::ExitCode {
    let cli = gaitlab::cli::Cli::parse();
    // Returned, not `process::exit`: destructors run and stdout is flushed on the way out.
    std::process::ExitCode::from(gaitlab::cli::run(cli))
}
