//! The `deckland` command line: trim, linearise, simulate and plot carrier landings
//! (the library's [`deckland_cli::main`]).

fn main() -> std::process::ExitCode {
    deckland_cli::main()
}
