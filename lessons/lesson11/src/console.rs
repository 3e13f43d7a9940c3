//! Standard output that neither a closed pipe nor a full disk can crash.
//!
//! `println!` panics when standard output fails: `lesson11 scenes | head -c 1`
//! died with "Broken pipe", and `stereo` with its output on a full device
//! wrote none of its files. Everything the program says goes through
//! `say!` and `say_inline!` instead: a
//! reader that went away (a closed pipe) silences the rest quietly; any other
//! failure (`/dev/full`) is named in one line on standard error, once. Either
//! way the work goes on and every file is written.

use std::io::{ErrorKind, Write};
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once standard output has failed: nothing more is written to it.
static SILENT: AtomicBool = AtomicBool::new(false);

/// Writes `args` to standard output, unless it has failed before.
pub fn write(args: std::fmt::Arguments) {
    if SILENT.load(Ordering::Relaxed) {
        return;
    }
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args) {
        if !SILENT.swap(true, Ordering::Relaxed) && e.kind() != ErrorKind::BrokenPipe {
            eprintln!("lesson11: cannot write to standard output ({e}); going on without it");
        }
    }
}

/// `println!` that cannot panic (see the module doc).
macro_rules! say {
    () => {
        $crate::console::write(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::console::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `print!` that cannot panic (see the module doc).
macro_rules! say_inline {
    ($($arg:tt)*) => {
        $crate::console::write(format_args!($($arg)*))
    };
}

pub(crate) use {say, say_inline};
