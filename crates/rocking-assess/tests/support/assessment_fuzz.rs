// What the `assessment` fuzz target does with one input, shared by the target
// (`fuzz/fuzz_targets/assessment.rs`, through `include!`) and the stable
// replay of the kept inputs (`tests/fuzz_corpora.rs`): the input is
// an assessment file's text, parsed and validated as `rocking assess` does,
// then the tower's capacity and its kinematic checks, and those of each block
// on it. The file may be refused with one line naming it, never a panic; what
// is accepted holds finite numbers.
//
// Nothing is read from disk and nothing is simulated: `assessment.records` is
// removed (a record set reads files or runs records through the model), and a
// `site.grid` given as a string is the synthetic hazard grid of the
// repository (`data/hazard/synthetic_grid.txt`), given as text.

/// Checks one fuzz input as an assessment file.
pub fn replay(data: &[u8]) {
    use rocking_assess::{AssessmentInput, Capacity, Check};
    use rocking_scenario::{parse_toml, AssessmentFile, GridCache};
    use std::path::Path;
    use toml::Value;

    let Ok(text) = std::str::from_utf8(data) else { return };
    let origin = Path::new("fuzz.toml");
    let refused = |e: rocking_scenario::Error| {
        let line = e.to_string();
        assert!(
            line.starts_with("fuzz.toml: ") && !line.contains('\n'),
            "not one line naming the file: {line:?}"
        );
    };
    let mut table = match parse_toml(text, origin) {
        Ok(table) => table,
        Err(e) => return refused(e),
    };
    if let Some(Value::Table(assessment)) = table.get_mut("assessment") {
        assessment.remove("records");
    }
    let grid = Path::new("grid.txt");
    if let Some(Value::Table(site)) = table.get_mut("site") {
        if let Some(Value::String(path)) = site.get_mut("grid") {
            *path = grid.display().to_string();
        }
    }
    let grids = GridCache::holding(grid, include_str!("../../../../data/hazard/synthetic_grid.txt")).expect("the synthetic grid reads");
    let input = match AssessmentFile::from_table_on(table, origin, &grids).and_then(AssessmentInput::new) {
        Ok(input) => input,
        Err(e) => return refused(e),
    };
    let finite_capacity = |c: &Capacity| {
        let all = [
            c.alpha,
            c.radius,
            c.g,
            c.confidence_factor,
            c.alpha0,
            c.e_star,
            c.m_star,
            c.a0_star,
            c.d0,
            c.d_slv,
            c.d_slc,
            c.t_slv,
            c.t_slc,
        ];
        assert!(all.iter().all(|x| x.is_finite()), "a capacity not finite: {c:?}");
    };
    let finite_check = |c: &Check| {
        let all = [c.demand, c.capacity, c.ag, c.ag_capacity.value(), c.zeta_e];
        assert!(all.iter().all(|x| x.is_finite()), "a check not finite: {c:?}");
    };
    for k in 0..=input.blocks().len() {
        let capacity = match input.block_capacity(k) {
            Ok(capacity) => capacity,
            Err(e) => return refused(e),
        };
        finite_capacity(&capacity);
        match input.kinematic_checks(&capacity) {
            Ok(checks) => checks.iter().for_each(finite_check),
            Err(e) => return refused(e),
        }
    }
}
