use clap::Parser;

fn main() {
    let cli = gaitlab::cli::Cli::parse();
    std::process::exit(gaitlab::cli::run(cli));
}
