//! The outputs reference `docs/src/reference/outputs.md` is the text generated
//! from the column descriptors, so it cannot drift from what the writers write.
//! `UPDATE_OUTPUTS_MD=1` rewrites the file instead of comparing.

use rocking_scenario::columns::outputs_markdown;
use std::path::Path;

#[test]
fn the_outputs_reference_is_the_generated_text() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/src/reference/outputs.md");
    let generated = outputs_markdown();
    if std::env::var_os("UPDATE_OUTPUTS_MD").is_some() {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
        }
        std::fs::write(&path, &generated).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
    let on_disk = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(
        on_disk == generated,
        "{} differs from the descriptors in crates/rocking-scenario/src/columns.rs; \
         regenerate it with UPDATE_OUTPUTS_MD=1 cargo test -p rocking-scenario --test outputs_reference",
        path.display()
    );
}
