//! What the `routh` binary writes, and its exit codes (issue 43): the figures of a run all or
//! none through the one writer (links written through, devices in place, modes kept, every
//! error naming its file), standard output that cannot be written, and the exit codes of
//! docs/cli.md — 0 success, 1 a failed computation (or an unwritable output), 2 bad input.

mod common;

use common::{routh, stderr, stdout, ASYMMETRIC, SWINGING, TOP};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// A fresh scratch directory.
fn scratch(case: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("routh-cli-files-{}-{case}", std::process::id()));
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

/// The names in `dir`, sorted (a temporary left behind shows here).
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[cfg(unix)]
fn mode(p: &Path) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(p).unwrap().permissions().mode() & 0o7777
}

#[cfg(unix)]
fn set_mode(p: &Path, m: u32) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(p, fs::Permissions::from_mode(m)).unwrap();
}

/// Root may write any file: the read-only case is skipped then.
#[cfg(unix)]
fn is_root(dir: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    let probe = dir.join("probe");
    fs::write(&probe, b"").unwrap();
    let uid = fs::metadata(&probe).unwrap().uid();
    fs::remove_file(&probe).unwrap();
    uid == 0
}

/// The runs that write two figures: the command, then its two figure options.
fn two_figure_runs() -> Vec<(Vec<&'static str>, [&'static str; 2])> {
    vec![
        (
            vec!["orbits", TOP, "--momentum", "0", "--max-orbits", "5"],
            ["--svg", "--periods-svg"],
        ),
        (
            vec!["diagram", TOP, "--momentum", "0..5"],
            ["--svg", "--energy-momentum-svg"],
        ),
    ]
}

/// `routh BASE FIRST first SECOND second`.
fn run_two(base: &[&str], opts: [&str; 2], first: &Path, second: &Path) -> std::process::Output {
    let mut args: Vec<&str> = base.to_vec();
    args.extend([
        opts[0],
        first.to_str().unwrap(),
        opts[1],
        second.to_str().unwrap(),
    ]);
    routh(&args)
}

const OLD: &[u8] = b"<svg>the figure of yesterday</svg>\n";

/// The hostile table of the figures of one run, for `orbits` and `diagram`: a second figure
/// that cannot be written leaves the first's old file byte-identical with its mode (all or
/// none), a link is written through, a device is written in place, a mode is kept, and no
/// temporary is left anywhere.
#[cfg(unix)]
#[test]
fn the_figures_of_a_run_are_written_all_or_none() {
    for (base, opts) in two_figure_runs() {
        let what = base[0];
        let d = scratch(what);
        let first = d.join("first.svg");
        let reset = || {
            fs::write(&first, OLD).unwrap();
            set_mode(&first, 0o640);
        };
        let intact = |case: &str| {
            assert_eq!(
                fs::read(&first).unwrap(),
                OLD,
                "{what}, {case}: first changed"
            );
            assert_eq!(mode(&first), 0o640, "{what}, {case}: mode changed");
        };

        // The second target is a directory: refused at the commit at the latest, the first put
        // back (before, the first was renamed into place and the second failed: a half set).
        reset();
        let sub = d.join("sub");
        fs::create_dir_all(&sub).unwrap();
        let o = run_two(&base, opts, &first, &sub);
        assert_eq!(o.status.code(), Some(1), "{what}: {}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("cannot write {}", sub.display())),
            "{what}: {}",
            stderr(&o)
        );
        assert!(stdout(&o).is_empty(), "{what}: {}", stdout(&o));
        intact("a directory second");
        assert_eq!(names(&d), ["first.svg", "sub"], "{what}: temporaries left");

        // The second is a full disk (a device, written last): the first put back.
        if Path::new("/dev/full").exists() {
            let o = run_two(&base, opts, &first, Path::new("/dev/full"));
            assert_eq!(o.status.code(), Some(1), "{what}: {}", stderr(&o));
            assert!(
                stderr(&o).contains("cannot write /dev/full"),
                "{what}: {}",
                stderr(&o)
            );
            intact("/dev/full second");
            assert_eq!(names(&d), ["first.svg", "sub"], "{what}: temporaries left");
        }

        // The second is in a missing directory: nothing is renamed.
        let missing = d.join("no/such/dir/second.svg");
        let o = run_two(&base, opts, &first, &missing);
        assert_eq!(o.status.code(), Some(1), "{what}: {}", stderr(&o));
        assert!(
            stderr(&o).contains(&format!("cannot write {}", missing.display())),
            "{what}: {}",
            stderr(&o)
        );
        intact("a missing directory");
        assert_eq!(names(&d), ["first.svg", "sub"], "{what}: temporaries left");

        // A read-only first figure is refused (as the user; root may write it).
        if !is_root(&d) {
            set_mode(&first, 0o444);
            let o = run_two(&base, opts, &first, &d.join("second.svg"));
            assert_eq!(o.status.code(), Some(1), "{what}: {}", stderr(&o));
            assert!(
                stderr(&o).contains(&format!("cannot write {}", first.display())),
                "{what}: {}",
                stderr(&o)
            );
            assert_eq!(fs::read(&first).unwrap(), OLD);
            assert!(!d.join("second.svg").exists());
            set_mode(&first, 0o640);
        }

        // A link is written through (the link stays a link, its target keeps its mode; the
        // temporary beside the target), a new file beside it; then /dev/null as the second is
        // written in place and stays a device.
        let t = scratch(&format!("{what}-target"));
        let target = t.join("real.svg");
        fs::write(&target, OLD).unwrap();
        set_mode(&target, 0o600);
        let link = d.join("link.svg");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let second = d.join("second.svg");
        let o = run_two(&base, opts, &link, &second);
        assert_eq!(o.status.code(), Some(0), "{what}: {}", stderr(&o));
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        let drawn = fs::read_to_string(&target).unwrap();
        assert!(drawn.contains("<svg"), "{what}: {drawn:.100}");
        assert_eq!(mode(&target), 0o600, "{what}: the target's mode");
        assert!(fs::read_to_string(&second).unwrap().contains("<svg"));
        assert_eq!(names(&t), ["real.svg"], "{what}: temporaries left");
        let o = run_two(&base, opts, &first, Path::new("/dev/null"));
        assert_eq!(o.status.code(), Some(0), "{what}: {}", stderr(&o));
        {
            use std::os::unix::fs::FileTypeExt;
            assert!(fs::metadata("/dev/null")
                .unwrap()
                .file_type()
                .is_char_device());
        }
        assert!(fs::read_to_string(&first).unwrap().contains("<svg"));
        assert_eq!(mode(&first), 0o640, "{what}: the first's mode");
        assert_eq!(
            names(&d),
            ["first.svg", "link.svg", "second.svg", "sub"],
            "{what}: temporaries left"
        );
        fs::remove_dir_all(&d).ok();
        fs::remove_dir_all(&t).ok();
    }
}

/// `section --svg`: a link written through, a mode kept, a directory refused and named.
#[cfg(unix)]
#[test]
fn the_section_figure_goes_through_the_writer() {
    let d = scratch("section");
    let t = scratch("section-target");
    let target = t.join("real.svg");
    fs::write(&target, OLD).unwrap();
    set_mode(&target, 0o600);
    let link = d.join("s.svg");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let base = [
        "section",
        ASYMMETRIC,
        "--momentum",
        "0",
        "--energy",
        "-1",
        "--orbits",
        "3",
        "--crossings",
        "10",
        "--svg",
    ];
    let with = |p: &Path| -> std::process::Output {
        let mut a = base.to_vec();
        a.push(p.to_str().unwrap());
        routh(&a)
    };
    let o = with(&link);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(fs::read_to_string(&target).unwrap().contains("<svg"));
    assert_eq!(mode(&target), 0o600);
    let o = with(&t);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(&format!("cannot write {}", t.display())),
        "{}",
        stderr(&o)
    );
    assert_eq!(names(&t), ["real.svg"]);
    assert_eq!(names(&d), ["s.svg"]);
    fs::remove_dir_all(&d).ok();
    fs::remove_dir_all(&t).ok();
}

/// Standard output that cannot be written, over the subcommands: a full disk is an error
/// ("cannot write to standard output", exit code 1), a closed pipe (`| head`) is quiet with
/// the status of a program ended by SIGPIPE, 141 (before, both exited 0).
#[cfg(unix)]
#[test]
fn standard_output_that_cannot_be_written_is_not_success() {
    let runs: &[&[&str]] = &[
        &["steady", TOP, "-p", "3"],
        &["classify", TOP, "-p", "3", "--json"],
        &["formulas", TOP],
        &["diagram", TOP, "--momentum", "0..5", "--csv"],
        &[
            "section",
            ASYMMETRIC,
            "-p",
            "0",
            "-e",
            "-1",
            "--orbits",
            "3",
            "--crossings",
            "10",
            "--csv",
        ],
    ];
    for args in runs {
        if Path::new("/dev/full").exists() {
            let full = fs::OpenOptions::new()
                .write(true)
                .open("/dev/full")
                .unwrap();
            let o = Command::new(env!("CARGO_BIN_EXE_routh"))
                .args(*args)
                .stdout(full)
                .output()
                .unwrap();
            assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
            assert!(
                stderr(&o).starts_with("error: cannot write to standard output: "),
                "{args:?}: {}",
                stderr(&o)
            );
        }
        // The reading end closed before routh writes (it loads and computes first).
        let mut child = Command::new(env!("CARGO_BIN_EXE_routh"))
            .args(*args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let o = child.wait_with_output().unwrap();
        assert_eq!(o.status.code(), Some(141), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).is_empty(), "{args:?}: {}", stderr(&o));
    }
}

/// docs/cli.md's exit codes over the subcommands: 0 success, 2 bad input (also what the
/// library refuses as input: an invalid option, an invalid model, …), 1 a failed computation
/// or an output that cannot be written.
#[test]
fn exit_codes_follow_the_docs() {
    let d = scratch("codes");
    let unwritable = d.join("no/such/dir/x.svg");
    let unwritable = unwritable.to_str().unwrap();
    let table: Vec<(Vec<&str>, i32, &str)> = vec![
        // Success.
        (vec!["steady", TOP, "-p", "3"], 0, ""),
        (vec!["classify", TOP, "-p", "3", "--axis", "0,0,1"], 0, ""),
        (vec!["nonlinear", TOP, "-p", "3"], 0, ""),
        (vec!["formulas", TOP], 0, ""),
        (vec!["diagram", TOP, "--momentum", "0..5"], 0, ""),
        (vec!["certify", TOP, "-p", "1.5"], 0, ""),
        (
            vec![
                "simulate", TOP, "--omega", "0,0,1", "--gamma", "0,0,1", "--t-end", "1",
            ],
            0,
            "",
        ),
        (
            vec!["orbits", TOP, "--momentum", "0", "--max-orbits", "3"],
            0,
            "",
        ),
        (
            vec![
                "section",
                ASYMMETRIC,
                "-p",
                "0",
                "-e",
                "-1",
                "--orbits",
                "3",
                "--crossings",
                "10",
            ],
            0,
            "",
        ),
        // Bad input, found by the command line.
        (vec!["frobnicate", TOP], 2, "frobnicate"),
        (
            vec!["steady", "no/such/model.toml", "-p", "1"],
            2,
            "no/such/model.toml",
        ),
        (vec!["diagram", TOP, "--momentum", "5..0"], 2, "inverted"),
        // Bad input that the library refuses (before: exit code 1).
        (
            vec!["section", ASYMMETRIC, "-p", "0", "-e", "-5"],
            2,
            "invalid option energy: no motion",
        ),
        (
            vec![
                "section", ASYMMETRIC, "-p", "0", "-e", "-1", "--normal", "0,0,0",
            ],
            2,
            "must be a non-zero vector",
        ),
        (
            vec!["classify", TOP, "-p", "3", "--axis", "1,0,0"],
            2,
            "not symmetric about the axis",
        ),
        (
            vec!["classify", TOP, "-p", "3", "--axis", "0,0,0"],
            2,
            "must be a non-zero vector",
        ),
        (
            vec![
                "orbit", SWINGING, "--omega", "0,0,0", "--gamma", "0,0,-1", "--period", "5",
            ],
            2,
            "the guess is a steady motion",
        ),
        // A failed computation.
        (vec!["steady", TOP, "-p", "1e308"], 1, "no convergence"),
        (
            vec![
                "orbit",
                SWINGING,
                "--omega",
                "3,2,1",
                "--gamma",
                "0.6,0,0.8",
                "--period",
                "0.01",
            ],
            1,
            "no periodic orbit from the guess",
        ),
        // An output that cannot be written.
        (
            vec!["diagram", TOP, "--momentum", "0..5", "--svg", unwritable],
            1,
            "cannot write",
        ),
        (
            vec![
                "section", ASYMMETRIC, "-p", "0", "-e", "-1", "--orbits", "3", "--svg", unwritable,
            ],
            1,
            "cannot write",
        ),
    ];
    for (args, code, needle) in &table {
        let o = routh(args);
        assert_eq!(o.status.code(), Some(*code), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{args:?}: {}", stderr(&o));
        if *code != 0 {
            assert!(stdout(&o).is_empty(), "{args:?}: {}", stdout(&o));
            assert!(
                stderr(&o).starts_with("error: "),
                "{args:?}: {}",
                stderr(&o)
            );
        }
    }
    fs::remove_dir_all(&d).ok();
}
