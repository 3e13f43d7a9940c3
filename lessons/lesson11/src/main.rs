//! `lesson11`, the program: everything it does is in the library, whose
//! documentation (`src/lib.rs`) says how it is laid out.

fn main() -> std::process::ExitCode {
    lesson11::main()
}
