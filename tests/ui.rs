//! Compile-fail tests of `#[derive(Lagrangian)]`: every mistake is a compile error at the user's
//! tokens, with no follow-on errors.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
