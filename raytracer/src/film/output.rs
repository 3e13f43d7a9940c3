//! Writing and reading images: tone-mapped 8-bit sRGB PNG and linear EXR.
//!
//! PNG is for looking at: the linear radiance is multiplied by `2^stops`
//! (exposure), clamped to `[0, 1]` and encoded with the exact sRGB transfer
//! curve (IEC 61966-2-1)
//!
//! ```text
//!   V = 12.92 · L                    for L ≤ 0.0031308
//!   V = 1.055 · L^(1/2.4) − 0.055    otherwise
//! ```
//!
//! then rounded to 8 bits. EXR is for measuring: linear float32 RGB,
//! unclamped, bit for bit what the film computed (references for the grader,
//! environment maps).
//!
//! The same pixels always give the same bytes, PNG and EXR alike (the EXR's
//! blocks are compressed and written in order, on one thread), so a rerun
//! with the same seed can be compared file by file.
//!
//! **No file is ever left half-written.** Every file goes first to a hidden
//! temporary file in the destination's folder (`.NAME.PID-N.tmp`), is
//! flushed to the disk (`fsync`), and is renamed over the destination once
//! complete ([`StagedFile`]). A rename within one folder replaces the file
//! in one step: a reader, a kill -9 or a full disk sees the old file or the
//! new one, never a truncated one.
//!
//! Files that belong together (a render's EXR, variance EXR and PNG) are
//! all written and synced first and only then renamed, in the order given,
//! by [`commit_all`]. What holds, exactly:
//!
//! - an error while writing them (a full disk, a permission) replaces none;
//! - a kill (kill -9, a crash of the program) before the first rename
//!   leaves every old file in place, with stale hidden `.tmp` files beside
//!   them;
//! - a kill *between* two renames, a window of microseconds, leaves the
//!   files renamed so far new and the rest old (a prefix of the order
//!   given), with the complete temporaries of the rest beside them;
//! - in every case each name holds the whole old file or the whole new one
//!   — after a power loss too, since the data is synced before the rename
//!   (which renames survive a power loss is then up to the file system: the
//!   folder itself is not synced).
//!
//! A second Ctrl-C, which quits at once ([`crate::render`]), goes through
//! [`exit_removing_staged_files`]: the temporaries of this process are
//! removed first (every [`StagedFile`] not yet committed is listed while it
//! exists), so only a kill -9 or a crash leaves them.
//!
//! Nothing finishes or removes the leftovers later. The set is not replaced
//! atomically as a whole: no file system call renames several names at
//! once, and the indirections that would (a folder or symlink per picture
//! swapped in one rename, or a journal replayed by every reader) would
//! change the flat output folders that pages and students rely on.
//!
//! Errors are `std::io::Error`s whose message names the file. Creating the
//! parent directory is the caller's job; a missing one is reported as such.

use super::Image;
use crate::math::Color;
use std::fs::{File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard};

/// The temporary files of the [`StagedFile`]s alive in this process.
static STAGED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn staged_list() -> MutexGuard<'static, Vec<PathBuf>> {
    STAGED
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Removes `temp` from the list of live temporaries.
fn unlist(list: &mut Vec<PathBuf>, temp: &Path) {
    if let Some(i) = list.iter().position(|p| p == temp) {
        list.swap_remove(i);
    }
}

/// Removes the temporary files of every [`StagedFile`] not yet committed,
/// then exits the process with `code`. The list stays locked until the
/// exit, so no staged file is created or renamed in between: each name
/// keeps its old file or its new one, and no `.tmp` file is left.
pub fn exit_removing_staged_files(code: i32) -> ! {
    let list = staged_list();
    for temp in list.iter() {
        let _ = std::fs::remove_file(temp);
    }
    std::process::exit(code)
}

/// The sRGB encoding `V(L)` of a linear value `L ∈ [0, 1]` (see the module doc).
#[inline]
pub fn linear_to_srgb(l: f32) -> f32 {
    if l <= 0.003_130_8 {
        12.92 * l
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    }
}

/// A linear value, scaled by `exposure`, clamped to `[0, 1]`, sRGB-encoded
/// and rounded to 8 bits (NaN gives 0).
#[inline]
pub fn srgb8(linear: f32) -> u8 {
    let l = if linear.is_nan() {
        0.0
    } else {
        linear.clamp(0.0, 1.0)
    };
    (linear_to_srgb(l) * 255.0).round() as u8
}

/// An error about the file at `path`.
fn error(path: &Path, what: &str, cause: impl std::fmt::Display, kind: io::ErrorKind) -> io::Error {
    io::Error::new(kind, format!("{what} {}: {cause}", path.display()))
}

/// Reports a missing parent directory clearly instead of a bare "No such file".
fn check_parent(path: &Path) -> io::Result<()> {
    match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() && !dir.is_dir() => Err(error(
            path,
            "cannot write",
            format_args!("the directory {} does not exist", dir.display()),
            io::ErrorKind::NotFound,
        )),
        _ => Ok(()),
    }
}

/// A complete file under a temporary name beside its destination, not yet in
/// place (see the module doc). [`StagedFile::commit`] renames it over the
/// destination; dropped without a commit, it removes the temporary file.
#[derive(Debug)]
#[must_use = "a staged file replaces its destination only once committed"]
pub struct StagedFile {
    temp: PathBuf,
    target: PathBuf,
    committed: bool,
}

impl StagedFile {
    /// Writes the new content of `target` with `fill` into a fresh temporary
    /// file in `target`'s folder and flushes it to the disk. `what` names the
    /// kind of file in errors ("PNG", "EXR", …). On an error the temporary
    /// file is removed and `target` is untouched.
    pub fn write(
        target: impl AsRef<Path>,
        what: &str,
        fill: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
    ) -> io::Result<StagedFile> {
        static COUNTER: AtomicU64 = AtomicU64::new(0);
        let target = target.as_ref().to_path_buf();
        check_parent(&target)?;
        let name = target.file_name().ok_or_else(|| {
            error(
                &target,
                "cannot write",
                "the path names no file",
                io::ErrorKind::InvalidInput,
            )
        })?;
        let temp = target.with_file_name(format!(
            ".{}.{}-{}.tmp",
            name.to_string_lossy(),
            std::process::id(),
            COUNTER.fetch_add(1, Ordering::Relaxed)
        ));
        // Listed before it exists (and under the lock): a quit in between
        // removes it or finds none.
        let file = {
            let mut list = staged_list();
            list.push(temp.clone());
            let file = OpenOptions::new().write(true).create_new(true).open(&temp);
            if file.is_err() {
                unlist(&mut list, &temp);
            }
            file.map_err(|e| error(&target, "cannot create", &e, e.kind()))?
        };
        // From here on, dropping `staged` removes the temporary file.
        let staged = StagedFile {
            temp,
            target,
            committed: false,
        };
        let mut writer = BufWriter::new(file);
        let written = fill(&mut writer)
            .and_then(|()| writer.flush())
            .and_then(|()| writer.get_ref().sync_all());
        match written {
            Ok(()) => Ok(staged),
            Err(e) => Err(error(
                &staged.target,
                &format!("cannot write {what}"),
                &e,
                e.kind(),
            )),
        }
    }

    /// The file this one will replace.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Renames the temporary file over the destination (one step: readers see
    /// the old file or the new one).
    pub fn commit(mut self) -> io::Result<()> {
        let mut list = staged_list();
        std::fs::rename(&self.temp, &self.target)
            .map_err(|e| error(&self.target, "cannot replace", &e, e.kind()))?;
        unlist(&mut list, &self.temp);
        self.committed = true;
        Ok(())
    }
}

impl Drop for StagedFile {
    fn drop(&mut self) {
        if !self.committed {
            let mut list = staged_list();
            let _ = std::fs::remove_file(&self.temp);
            unlist(&mut list, &self.temp);
        }
    }
}

/// Puts files that belong together in place, in the order given, once all of
/// them were written and synced (see the module doc for what a crash in
/// between leaves: a prefix of them new, the rest old).
pub fn commit_all(files: impl IntoIterator<Item = StagedFile>) -> io::Result<()> {
    files.into_iter().try_for_each(StagedFile::commit)
}

/// Writes `bytes` to `path` through a temporary file (see [`StagedFile`]):
/// the old file stays whole until the new one is.
pub fn write_file(path: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<()> {
    StagedFile::write(path, "the file", |w| w.write_all(bytes.as_ref()))?.commit()
}

impl Image {
    /// The 8-bit sRGB bytes (RGB, row by row) of the image scaled by
    /// `2^exposure_stops`.
    pub fn to_srgb8(&self, exposure_stops: f32) -> Vec<u8> {
        let scale = exposure_stops.exp2();
        self.pixels
            .iter()
            .flat_map(|&c| {
                let c: Color = c * scale;
                [srgb8(c.x), srgb8(c.y), srgb8(c.z)]
            })
            .collect()
    }

    /// Writes an 8-bit sRGB PNG of the image scaled by `2^exposure_stops`
    /// (0 = as rendered, +1 = twice as bright), replacing `path` in one step.
    pub fn write_png(&self, path: impl AsRef<Path>, exposure_stops: f32) -> io::Result<()> {
        self.stage_png(path, exposure_stops)?.commit()
    }

    /// The PNG of [`Image::write_png`], written but not yet in place.
    pub fn stage_png(&self, path: impl AsRef<Path>, exposure_stops: f32) -> io::Result<StagedFile> {
        StagedFile::write(path, "PNG", |w| self.encode_png(w, exposure_stops))
    }

    /// The bytes of the PNG file [`Image::write_png`] writes (a server's answer).
    pub fn png_bytes(&self, exposure_stops: f32) -> io::Result<Vec<u8>> {
        let mut bytes = Vec::new();
        self.encode_png(&mut bytes, exposure_stops)?;
        Ok(bytes)
    }

    fn encode_png(&self, w: impl Write, exposure_stops: f32) -> io::Result<()> {
        let bytes = self.to_srgb8(exposure_stops);
        let as_io = |e: png::EncodingError| match e {
            png::EncodingError::IoError(e) => e,
            e => io::Error::other(e),
        };
        let mut encoder = png::Encoder::new(w, self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        // The values are sRGB-encoded: say so in the file (its sRGB chunk).
        encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        let mut writer = encoder.write_header().map_err(as_io)?;
        writer.write_image_data(&bytes).map_err(as_io)?;
        writer.finish().map_err(as_io)
    }

    /// Writes the image as a linear, unclamped float32 RGB OpenEXR file,
    /// replacing `path` in one step.
    pub fn write_exr(&self, path: impl AsRef<Path>) -> io::Result<()> {
        self.stage_exr(path)?.commit()
    }

    /// The EXR of [`Image::write_exr`], written but not yet in place. Its
    /// blocks are written in order on one thread (the `exr` crate's parallel
    /// writer puts them in the order they finish): same pixels, same bytes.
    pub fn stage_exr(&self, path: impl AsRef<Path>) -> io::Result<StagedFile> {
        StagedFile::write(path, "EXR", |w| self.encode_exr(w))
    }

    /// The bytes of the EXR file [`Image::write_exr`] writes (a server's answer).
    pub fn exr_bytes(&self) -> io::Result<Vec<u8>> {
        let mut bytes = io::Cursor::new(Vec::new());
        self.encode_exr(&mut bytes)?;
        Ok(bytes.into_inner())
    }

    fn encode_exr(&self, w: impl Write + io::Seek) -> io::Result<()> {
        use exr::prelude::{Image as ExrImage, SpecificChannels, Vec2, WritableImage};
        let width = self.width as usize;
        let channels = SpecificChannels::rgb(|Vec2(x, y): Vec2<usize>| {
            let c = self.pixels[y * width + x];
            (c.x, c.y, c.z)
        });
        let image = ExrImage::from_channels((width, self.height as usize), channels);
        image
            .write()
            .non_parallel()
            .to_buffered(w)
            .map_err(|e| match e {
                exr::error::Error::Io(e) => e,
                e => io::Error::other(e),
            })
    }

    /// Reads the first RGB(A) layer of an OpenEXR file (alpha is ignored;
    /// half and integer channels are converted to f32).
    pub fn read_exr(path: impl AsRef<Path>) -> io::Result<Image> {
        let path = path.as_ref();
        let read = exr::prelude::read_first_rgba_layer_from_file(
            path,
            |size, _| Image::new(size.width() as u32, size.height() as u32),
            |image: &mut Image, pos, (r, g, b, _a): (f32, f32, f32, f32)| {
                image.set(pos.x() as u32, pos.y() as u32, Color::new(r, g, b));
            },
        )
        .map_err(|e| match e {
            exr::error::Error::Io(io) => error(path, "cannot read EXR", &io, io.kind()),
            e => error(path, "cannot read EXR", e, io::ErrorKind::InvalidData),
        })?;
        Ok(read.layer_data.channel_data.pixels)
    }
}

/// A decoder's error message on one line (some end theirs with a newline,
/// or list causes on lines of their own): what a file-reading error says
/// after the file's name.
pub fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
}
