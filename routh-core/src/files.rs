//! Writing files: the one writer of every face of routh — [`write_csv`](crate::Trajectory::write_csv)
//! here, the figures of `routh::plot`, the files of the `routh` command (all or none, through
//! [`Staged`]) and the Python package's `to_csv`.
//!
//! [`write_file`] writes `bytes` to `path` whole or not at all:
//!
//! - a regular file (new or existing) is written to a temporary file in the same directory
//!   (`.NAME.routh-PID-N.tmp`), which is flushed to disk (`fsync`) and then renamed over `path`:
//!   a reader sees the old contents or the new ones, never a part, and an error (a full disk, a
//!   directory as `path`, a missing directory) leaves `path` as it was and no temporary behind;
//! - an existing file keeps its permission bits; a new one gets `0666` less the umask (as a
//!   shell's `>` would give it);
//! - permission is checked as the caller's: an existing file that the caller cannot write is
//!   refused (a permission error), not replaced by the rename (which needs only the directory);
//! - a symbolic link is written through: its target (followed to the end, created if the link
//!   dangles) is replaced as above, the temporary beside the target, and the link stays a link;
//! - what is not a regular file — a named pipe, a terminal or another device, and anything
//!   reached through `/dev/fd/N`, `/dev/stdout` or `/proc/…/fd/N` — is opened and written
//!   directly, with no temporary and no rename (`/dev/stdout` is never replaced, even by root).
//!
//! Every error is an [`io::Error`] of the underlying kind whose message names the path
//! (`cannot write PATH: REASON`); its inner error is a [`WriteError`] with the path and the OS
//! error.
//!
//! ```
//! let dir = std::env::temp_dir().join(format!("routh-doc-files-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let path = dir.join("motions.csv");
//! routh_core::files::write_file(&path, b"p_psi,energy\n3,4.5\n")?;
//! assert_eq!(std::fs::read_to_string(&path)?, "p_psi,energy\n3,4.5\n");
//! // A directory is not a file: refused, named, and left as it was.
//! let err = routh_core::files::write_file(&dir, b"x").unwrap_err();
//! assert!(err.to_string().starts_with(&format!("cannot write {}: ", dir.display())));
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), std::io::Error>(())
//! ```

use std::fmt;
use std::fs::{self, File, OpenOptions, Permissions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// A write that failed: the path as the caller gave it and the I/O error. It is the inner error
/// (`io::Error::get_ref`) of the errors of this module, whose kind is that of
/// [`WriteError::io_error`].
#[derive(Debug)]
pub struct WriteError {
    path: PathBuf,
    source: io::Error,
}

impl WriteError {
    /// The path that could not be written, as given.
    pub fn path(&self) -> &Path {
        &self.path
    }
    /// Why (its `raw_os_error` is the OS error number where there is one).
    pub fn io_error(&self) -> &io::Error {
        &self.source
    }
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "cannot write {}: {}", self.path.display(), self.source)
    }
}

impl std::error::Error for WriteError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.source)
    }
}

/// `source` as the `io::Error` of this module: its kind, naming `path`.
fn named(path: &Path, source: io::Error) -> io::Error {
    io::Error::new(
        source.kind(),
        WriteError {
            path: path.to_path_buf(),
            source,
        },
    )
}

/// Writes `bytes` to `path`, whole or not at all (the rules in the [module
/// documentation](self)).
///
/// Errors: an [`io::Error`] naming `path` (a missing directory, a directory as `path`, no
/// permission, a full disk, …); `path` is then as it was and no temporary file is left.
pub fn write_file(path: impl AsRef<Path>, bytes: &[u8]) -> io::Result<()> {
    let path = path.as_ref();
    let written = match plan(path) {
        Ok(Plan::Direct(target)) => write_direct(&target, bytes),
        Ok(Plan::Replace { target, perms }) => {
            prepare(&target, perms, bytes).and_then(|tmp| rename_into(&tmp, &target))
        }
        Err(e) => Err(e),
    };
    written.map_err(|e| named(path, e))
}

/// How a path is written.
enum Plan {
    /// Opened and written in place (a pipe, a device, a `/dev/fd/N`).
    Direct(PathBuf),
    /// A regular file, new or existing (`perms`: its permissions), replaced through a temporary
    /// beside it; `target` is the path with its symbolic links followed.
    Replace {
        target: PathBuf,
        perms: Option<Permissions>,
    },
}

/// The paths whose files are other open files of the process: never replaced.
fn is_descriptor(p: &Path) -> bool {
    p.starts_with("/proc") || p.starts_with("/dev/fd")
}

/// Follows the symbolic links of `path`'s last component and decides how to write it; checks
/// that an existing file can be written by the caller.
fn plan(path: &Path) -> io::Result<Plan> {
    if path.as_os_str().is_empty() {
        return Err(io::Error::new(io::ErrorKind::NotFound, "empty path"));
    }
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        if is_descriptor(&p) {
            return Ok(Plan::Direct(path.to_path_buf()));
        }
        let meta = match fs::symlink_metadata(&p) {
            Ok(m) => m,
            // A new file (or the target of a dangling link); a missing directory is reported
            // when the temporary is created in it.
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                return Ok(Plan::Replace {
                    target: p,
                    perms: None,
                })
            }
            Err(e) => return Err(e),
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            let to = fs::read_link(&p)?;
            p = match p.parent() {
                Some(dir) if to.is_relative() => dir.join(to),
                _ => to,
            };
        } else if kind.is_dir() {
            return Err(not_a_file(&p));
        } else if kind.is_file() {
            // As the caller: opening for writing (not truncating) fails where the caller may
            // not write the file, although the rename would replace it.
            OpenOptions::new().write(true).open(&p)?;
            return Ok(Plan::Replace {
                target: p,
                perms: Some(meta.permissions()),
            });
        } else {
            return Ok(Plan::Direct(p));
        }
    }
    // The system's own error (ELOOP) where it gives one.
    Err(fs::metadata(path)
        .err()
        .unwrap_or_else(|| io::Error::other("too many levels of symbolic links")))
}

/// The error of writing the directory `dir`: the system's own (EISDIR, with its number) where
/// it gives one.
fn not_a_file(dir: &Path) -> io::Error {
    OpenOptions::new()
        .write(true)
        .open(dir)
        .err()
        .unwrap_or_else(|| io::Error::new(io::ErrorKind::IsADirectory, "is a directory"))
}

/// Writes `bytes` into the file at `target` as it is (no temporary, no rename).
fn write_direct(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut f = OpenOptions::new().write(true).truncate(true).open(target)?;
    f.write_all(bytes)?;
    f.flush()
}

/// The temporary file beside `target`, holding `bytes`, with `perms` (or `0666` less the umask),
/// flushed to disk. Removed again on an error.
fn prepare(target: &Path, perms: Option<Permissions>, bytes: &[u8]) -> io::Result<PathBuf> {
    let (tmp, mut file) = create_beside(target, "tmp")?;
    let filled = (|| {
        file.write_all(bytes)?;
        if let Some(p) = perms {
            file.set_permissions(p)?;
        }
        file.sync_all()
    })();
    drop(file);
    match filled {
        Ok(()) => Ok(tmp),
        Err(e) => {
            let _ = fs::remove_file(&tmp);
            Err(e)
        }
    }
}

/// Renames the temporary `tmp` over `target` (removing it on an error) and flushes the
/// directory.
fn rename_into(tmp: &Path, target: &Path) -> io::Result<()> {
    if let Err(e) = fs::rename(tmp, target) {
        let _ = fs::remove_file(tmp);
        return Err(e);
    }
    sync_dir(target);
    Ok(())
}

/// The directory of `target` (`.` for a bare name).
fn dir_of(target: &Path) -> &Path {
    match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// A new file `.NAME.routh-PID-N.SUFFIX` beside `target`, created exclusively (`0666` less the
/// umask on Unix).
fn create_beside(target: &Path, suffix: &str) -> io::Result<(PathBuf, File)> {
    static SERIAL: AtomicU64 = AtomicU64::new(0);
    let name: String = target
        .file_name()
        .map(|n| n.to_string_lossy().chars().take(100).collect())
        .unwrap_or_else(|| "output".into());
    let mut last = None;
    for _ in 0..100 {
        let tmp = dir_of(target).join(format!(
            ".{name}.routh-{}-{}.{suffix}",
            std::process::id(),
            SERIAL.fetch_add(1, Ordering::Relaxed)
        ));
        let mut opts = OpenOptions::new();
        opts.write(true).create_new(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut opts, 0o666);
        match opts.open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| io::Error::other("no temporary file name free")))
}

/// Flushes the directory entry of `target` to disk, where the system can (best effort).
fn sync_dir(target: &Path) {
    #[cfg(unix)]
    if let Ok(d) = File::open(dir_of(target)) {
        let _ = d.sync_all();
    }
    #[cfg(not(unix))]
    let _ = target;
}

/// The files of one run, written all or none: each [`Staged::write`] prepares its file (a
/// temporary beside a regular file, written and flushed; the bytes of a pipe or device kept),
/// and [`Staged::commit`] renames every temporary over its target and then writes the pipes and
/// devices. If any of it fails, the files already renamed are put back as they were, and
/// dropping a `Staged` without committing removes its temporaries: a failed run leaves every
/// existing file as it was.
///
/// ```
/// use routh_core::files::Staged;
/// let dir = std::env::temp_dir().join(format!("routh-doc-staged-{}", std::process::id()));
/// std::fs::create_dir_all(&dir)?;
/// let mut files = Staged::new();
/// files.write(dir.join("a.csv"), b"x\n1\n")?;
/// // A second file that cannot be written: the run fails and `a.csv` is never made.
/// assert!(files.write(dir.join("no/such/dir/b.csv"), b"y\n").is_err());
/// drop(files);
/// assert_eq!(std::fs::read_dir(&dir)?.count(), 0);
/// # std::fs::remove_dir_all(&dir)?;
/// # Ok::<(), std::io::Error>(())
/// ```
#[derive(Debug, Default)]
pub struct Staged {
    files: Vec<StagedFile>,
}

#[derive(Debug)]
struct StagedFile {
    /// The path as given (for messages).
    shown: PathBuf,
    how: StagedHow,
}

#[derive(Debug)]
enum StagedHow {
    /// The temporary `tmp` is renamed over `target` (the path with its links followed).
    Replace { target: PathBuf, tmp: PathBuf },
    /// `bytes` are written to `target` directly.
    Direct { target: PathBuf, bytes: Vec<u8> },
}

impl Staged {
    /// No files yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Prepares `bytes` for `path` (the rules of [`write_file`]); nothing is visible at `path`
    /// before [`Staged::commit`]. A second write to the same file replaces the first.
    ///
    /// Errors: as [`write_file`]'s, at once (a missing directory, a directory as `path`, no
    /// permission, a full disk); the files staged before are kept (to be dropped).
    pub fn write(&mut self, path: impl AsRef<Path>, bytes: &[u8]) -> io::Result<()> {
        let path = path.as_ref();
        let how = match plan(path).map_err(|e| named(path, e))? {
            Plan::Direct(target) => StagedHow::Direct {
                target,
                bytes: bytes.to_vec(),
            },
            Plan::Replace { target, perms } => {
                let tmp = prepare(&target, perms, bytes).map_err(|e| named(path, e))?;
                if let Some(i) = self.files.iter().position(
                    |f| matches!(&f.how, StagedHow::Replace { target: t, .. } if *t == target),
                ) {
                    drop(self.files.remove(i));
                }
                StagedHow::Replace { target, tmp }
            }
        };
        self.files.push(StagedFile {
            shown: path.to_path_buf(),
            how,
        });
        Ok(())
    }

    /// Renames every temporary over its target, then writes the pipes and devices. On an error
    /// (named), the files renamed so far are put back as they were (the old contents, or no file
    /// where there was none) and the temporaries are removed.
    pub fn commit(mut self) -> io::Result<()> {
        let files = std::mem::take(&mut self.files);
        // Each target renamed over, with the backup of its old contents (`None`: it was new).
        let mut done: Vec<(PathBuf, Option<PathBuf>)> = Vec::new();
        let mut result = Ok(());
        for f in &files {
            let StagedHow::Replace { target, tmp } = &f.how else {
                continue;
            };
            match replace_keeping(target, tmp) {
                Ok(backup) => done.push((target.clone(), backup)),
                Err(e) => {
                    result = Err(named(&f.shown, e));
                    break;
                }
            }
        }
        if result.is_ok() {
            for f in &files {
                if let StagedHow::Direct { target, bytes } = &f.how {
                    if let Err(e) = write_direct(target, bytes) {
                        result = Err(named(&f.shown, e));
                        break;
                    }
                }
            }
        }
        // Back out on an error; drop the backups on success.
        for (target, backup) in done.into_iter().rev() {
            match (&result, backup) {
                (Ok(()), Some(b)) => {
                    let _ = fs::remove_file(b);
                }
                (Ok(()), None) => {}
                (Err(_), Some(b)) => {
                    let _ = fs::rename(b, &target);
                }
                (Err(_), None) => {
                    let _ = fs::remove_file(&target);
                }
            }
        }
        // `files` drops here: the temporaries not renamed (after an error) are removed.
        drop(files);
        result
    }
}

/// Renames `tmp` over `target` after linking (or copying) the old `target`, if any, to a backup
/// beside it, which it returns. The target is checked again first: a directory that appeared
/// since it was staged is refused.
fn replace_keeping(target: &Path, tmp: &Path) -> io::Result<Option<PathBuf>> {
    let backup = match fs::symlink_metadata(target) {
        Ok(m) if m.is_dir() => return Err(not_a_file(target)),
        Ok(_) => backup_of(target),
        Err(_) => None,
    };
    match fs::rename(tmp, target) {
        Ok(()) => {
            sync_dir(target);
            Ok(backup)
        }
        Err(e) => {
            if let Some(b) = backup {
                let _ = fs::remove_file(b);
            }
            Err(e)
        }
    }
}

/// A second name (a hard link, else a copy) of the file `target`, beside it; `None` where
/// neither can be made (the file is then replaced without a way back).
fn backup_of(target: &Path) -> Option<PathBuf> {
    let (b, file) = create_beside(target, "old").ok()?;
    drop(file);
    let _ = fs::remove_file(&b);
    if fs::hard_link(target, &b).is_ok() || fs::copy(target, &b).is_ok() {
        Some(b)
    } else {
        let _ = fs::remove_file(&b);
        None
    }
}

impl Drop for StagedFile {
    /// Removes the temporary of a file not committed (a rename already done leaves nothing to
    /// remove).
    fn drop(&mut self) {
        if let StagedHow::Replace { tmp, .. } = &self.how {
            let _ = fs::remove_file(tmp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(unix)]
    use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};

    /// A fresh directory for one case.
    fn scratch(case: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("routh-writer-{}-{case}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    /// The names in `dir`, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    /// The error's message names `path` and its inner error is a `WriteError` for it.
    fn names_path(e: &io::Error, path: &Path) {
        assert!(
            e.to_string()
                .starts_with(&format!("cannot write {}: ", path.display())),
            "{e}"
        );
        let inner = e.get_ref().and_then(|r| r.downcast_ref::<WriteError>());
        assert_eq!(inner.map(WriteError::path), Some(path), "{e:?}");
    }

    #[cfg(unix)]
    fn mode(p: &Path) -> u32 {
        fs::metadata(p).unwrap().permissions().mode() & 0o7777
    }

    /// Root may write any file: the permission case is skipped then.
    #[cfg(unix)]
    fn is_root(dir: &Path) -> bool {
        let probe = dir.join("probe");
        fs::write(&probe, b"").unwrap();
        let uid = fs::metadata(&probe).unwrap().uid();
        fs::remove_file(&probe).unwrap();
        uid == 0
    }

    /// The hostile table: every kind of path `write_file` meets, each with what it
    /// must leave behind.
    #[cfg(unix)]
    #[test]
    fn writer_hostile_paths() {
        // A new file: 0666 less the umask (what `File::create` gives), never 0600.
        let d = scratch("new");
        let umasked = {
            fs::File::create(d.join("probe")).unwrap();
            let m = mode(&d.join("probe"));
            fs::remove_file(d.join("probe")).unwrap();
            m
        };
        write_file(d.join("a.csv"), b"new\n").unwrap();
        assert_eq!(fs::read(d.join("a.csv")).unwrap(), b"new\n");
        assert_eq!(mode(&d.join("a.csv")), umasked);
        assert_eq!(names(&d), ["a.csv"]);

        // An existing file keeps its mode and is replaced whole.
        let p = d.join("a.csv");
        fs::set_permissions(&p, Permissions::from_mode(0o640)).unwrap();
        write_file(&p, b"second\n").unwrap();
        assert_eq!(fs::read(&p).unwrap(), b"second\n");
        assert_eq!(mode(&p), 0o640);
        fs::set_permissions(&p, Permissions::from_mode(0o755)).unwrap();
        write_file(&p, b"third\n").unwrap();
        assert_eq!(mode(&p), 0o755);
        assert_eq!(names(&d), ["a.csv"]);

        // A read-only file the caller may not write is refused, not replaced by the rename.
        let ro = d.join("ro.csv");
        fs::write(&ro, b"keep\n").unwrap();
        fs::set_permissions(&ro, Permissions::from_mode(0o444)).unwrap();
        if !is_root(&d) {
            let e = write_file(&ro, b"x").unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::PermissionDenied, "{e}");
            names_path(&e, &ro);
            assert_eq!(fs::read(&ro).unwrap(), b"keep\n");
        } else {
            // Root may write it: written, and still 0444.
            write_file(&ro, b"root\n").unwrap();
            assert_eq!(fs::read(&ro).unwrap(), b"root\n");
        }
        assert_eq!(mode(&ro), 0o444);
        assert_eq!(names(&d), ["a.csv", "ro.csv"]);
        fs::set_permissions(&ro, Permissions::from_mode(0o644)).unwrap();

        // A symbolic link is written through: the target replaced (temporary beside it, in its
        // own directory), the link still a link; a relative link, and a chain of two.
        let t = scratch("target");
        let target = t.join("real.csv");
        fs::write(&target, b"old\n").unwrap();
        fs::set_permissions(&target, Permissions::from_mode(0o600)).unwrap();
        let link = d.join("link.csv");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_file(&link, b"through\n").unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read(&target).unwrap(), b"through\n");
        assert_eq!(mode(&target), 0o600);
        let rel = d.join("rel.csv");
        std::os::unix::fs::symlink("link.csv", &rel).unwrap();
        write_file(&rel, b"chain\n").unwrap();
        assert!(fs::symlink_metadata(&rel).unwrap().file_type().is_symlink());
        assert_eq!(fs::read(&target).unwrap(), b"chain\n");
        assert_eq!(names(&t), ["real.csv"]);

        // A dangling link: its target is created; the link stays.
        let dangling = d.join("dangling.csv");
        std::os::unix::fs::symlink(t.join("made.csv"), &dangling).unwrap();
        write_file(&dangling, b"made\n").unwrap();
        assert!(fs::symlink_metadata(&dangling)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read(t.join("made.csv")).unwrap(), b"made\n");
        assert_eq!(names(&t), ["made.csv", "real.csv"]);
        // A loop of links: an error, named.
        let looped = d.join("loop.csv");
        std::os::unix::fs::symlink("loop.csv", &looped).unwrap();
        names_path(&write_file(&looped, b"x").unwrap_err(), &looped);

        // A directory: refused, named, untouched, no temporary beside it.
        let sub = d.join("sub");
        fs::create_dir(&sub).unwrap();
        fs::write(sub.join("keep"), b"k").unwrap();
        let e = write_file(&sub, b"x").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::IsADirectory);
        names_path(&e, &sub);
        assert_eq!(names(&sub), ["keep"]);
        // A missing directory: not found, named.
        let missing = d.join("no/such/dir/x.csv");
        let e = write_file(&missing, b"x").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::NotFound);
        names_path(&e, &missing);
        // Below a file: not a directory, named.
        let below = d.join("a.csv/x.csv");
        names_path(&write_file(&below, b"x").unwrap_err(), &below);
        assert_eq!(
            names(&d),
            [
                "a.csv",
                "dangling.csv",
                "link.csv",
                "loop.csv",
                "rel.csv",
                "ro.csv",
                "sub"
            ]
        );

        // Devices are written in place: /dev/null stays a device; /dev/full's error is named.
        write_file("/dev/null", b"nothing\n").unwrap();
        assert!(fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device());
        if Path::new("/dev/full").exists() {
            let e = write_file("/dev/full", b"x").unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::StorageFull, "{e}");
            names_path(&e, Path::new("/dev/full"));
        }
        // /dev/stdout is never replaced (not even by root): it is planned as written in place.
        // Not written here: the test's own standard output may be a file (`cargo test > log`),
        // which an empty write in place would truncate.
        if fs::symlink_metadata("/dev/stdout").is_ok() {
            assert!(matches!(
                plan(Path::new("/dev/stdout")).unwrap(),
                Plan::Direct(_)
            ));
        }
        // An open descriptor through /dev/fd/N: written into the pipe, nothing replaced.
        if Path::new("/dev/fd").exists() {
            use std::io::Read;
            use std::os::fd::AsRawFd;
            let (mut r, w) = io::pipe().unwrap();
            write_file(format!("/dev/fd/{}", w.as_raw_fd()), b"piped\n").unwrap();
            drop(w);
            let mut got = String::new();
            r.read_to_string(&mut got).unwrap();
            assert_eq!(got, "piped\n");
        }
        // A named pipe: written directly, no temporary beside it, still a pipe.
        let fifo = d.join("fifo");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let reader = {
                let fifo = fifo.clone();
                std::thread::spawn(move || fs::read(fifo).unwrap())
            };
            write_file(&fifo, b"through the pipe\n").unwrap();
            assert_eq!(reader.join().unwrap(), b"through the pipe\n");
            assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
            fs::remove_file(&fifo).unwrap();
        }
        assert_eq!(
            names(&d),
            [
                "a.csv",
                "dangling.csv",
                "link.csv",
                "loop.csv",
                "rel.csv",
                "ro.csv",
                "sub"
            ]
        );
        fs::remove_dir_all(&d).unwrap();
        fs::remove_dir_all(&t).unwrap();
    }

    /// Staged files: all or none, through a failure at staging, at the rename, and at a device
    /// written last.
    #[cfg(unix)]
    #[test]
    fn writer_staged_all_or_none() {
        let d = scratch("staged");
        let a = d.join("a.svg");
        let b = d.join("b.svg");
        fs::write(&a, b"old a\n").unwrap();
        fs::set_permissions(&a, Permissions::from_mode(0o604)).unwrap();

        // Both written at the commit, none before; modes as write_file's.
        let mut s = Staged::new();
        s.write(&a, b"new a\n").unwrap();
        s.write(&b, b"new b\n").unwrap();
        assert_eq!(fs::read(&a).unwrap(), b"old a\n");
        assert!(!b.exists());
        s.commit().unwrap();
        assert_eq!(fs::read(&a).unwrap(), b"new a\n");
        assert_eq!(fs::read(&b).unwrap(), b"new b\n");
        assert_eq!(mode(&a), 0o604);
        assert_eq!(names(&d), ["a.svg", "b.svg"]);

        // The second cannot be staged (a directory): dropped, the first untouched.
        let sub = d.join("sub");
        fs::create_dir(&sub).unwrap();
        let mut s = Staged::new();
        s.write(&a, b"lost\n").unwrap();
        names_path(&s.write(&sub, b"x").unwrap_err(), &sub);
        drop(s);
        assert_eq!(fs::read(&a).unwrap(), b"new a\n");
        assert_eq!(names(&d), ["a.svg", "b.svg", "sub"]);

        // The second target becomes a directory after staging: the commit fails on it and
        // puts the first back (old contents and mode); a new file of the run is removed.
        let c = d.join("c.svg");
        let mut s = Staged::new();
        s.write(&a, b"lost\n").unwrap();
        s.write(&c, b"lost\n").unwrap();
        s.write(&b, b"lost\n").unwrap();
        fs::remove_file(&b).unwrap();
        fs::create_dir(&b).unwrap();
        let e = s.commit().unwrap_err();
        names_path(&e, &b);
        assert_eq!(fs::read(&a).unwrap(), b"new a\n");
        assert_eq!(mode(&a), 0o604);
        assert!(!c.exists());
        assert_eq!(names(&d), ["a.svg", "b.svg", "sub"]);
        fs::remove_dir(&b).unwrap();

        // A device written after the renames fails: the renames are undone.
        if Path::new("/dev/full").exists() {
            let mut s = Staged::new();
            s.write(&a, b"lost\n").unwrap();
            s.write("/dev/full", b"x").unwrap();
            let e = s.commit().unwrap_err();
            names_path(&e, Path::new("/dev/full"));
            assert_eq!(fs::read(&a).unwrap(), b"new a\n");
            assert_eq!(names(&d), ["a.svg", "sub"]);
        }

        // The same file twice: the last write wins, one temporary.
        let mut s = Staged::new();
        s.write(&a, b"first\n").unwrap();
        s.write(&a, b"last\n").unwrap();
        s.commit().unwrap();
        assert_eq!(fs::read(&a).unwrap(), b"last\n");
        assert_eq!(names(&d), ["a.svg", "sub"]);
        fs::remove_dir_all(&d).unwrap();
    }
}
