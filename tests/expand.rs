//! Expansion snapshots (after pin-project's `expandtest.rs`): every `examples/expanded/NAME.rs`
//! is expanded with the code generator and compared with `NAME.expanded.rs`, so that any change
//! to generated code shows up in review. `ROUTH_BLESS=1 cargo test --test main expand::` rewrites them.

use std::path::Path;

fn expand_file(path: &Path) -> String {
    let src = std::fs::read_to_string(path).expect("read model");
    let file: syn::File = syn::parse_str(&src).expect("parse model");
    let mut out = syn::File {
        shebang: None,
        attrs: vec![],
        items: vec![],
    };
    for item in file.items {
        if let syn::Item::Struct(s) = &item {
            let tokens = routh_codegen::derive(quote_item(s));
            let expanded: syn::File = syn::parse2(tokens).expect("generated code parses");
            out.items.push(item.clone());
            out.items.extend(expanded.items);
        }
    }
    prettyplease::unparse(&out)
}

fn quote_item(s: &syn::ItemStruct) -> proc_macro2::TokenStream {
    use quote::ToTokens;
    s.to_token_stream()
}

#[test]
fn expansions_match_snapshots() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/expanded");
    let bless = std::env::var_os("ROUTH_BLESS").is_some();
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("examples/expanded") {
        let path = entry.expect("entry").path();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_string();
        if !name.ends_with(".rs") || name.ends_with(".expanded.rs") {
            continue;
        }
        let expanded = expand_file(&path);
        let snap = path.with_file_name(name.replace(".rs", ".expanded.rs"));
        if bless {
            std::fs::write(&snap, &expanded).expect("write snapshot");
        } else {
            let old = std::fs::read_to_string(&snap).unwrap_or_default();
            assert!(
                old == expanded,
                "generated code for {name} changed; review and run `ROUTH_BLESS=1 cargo test --test main expand::`\n--- new ---\n{expanded}"
            );
        }
        checked += 1;
    }
    assert!(checked > 0, "no models in examples/expanded");
}
