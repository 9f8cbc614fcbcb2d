//! The mechanisms of a stack (a belfry on its shaft, a lantern on the belfry)
//! against numbers worked out by hand from the formulas of the capacity
//! (Circolare 2019 §C8.7.1.2.1.3–C8.7.1.2.1.7): each block with the blocks
//! above it is one rigid body turning about a corner of its base, `b` half its
//! width, `h` the height of their centre of mass above its base, M* their
//! mass; the tower's mechanism is the whole stack's. The kinematic checks of a
//! block read the ground's spectra (the shaft's top moves with the ground
//! while the shaft stands).
//!
//! The shaft is the tests' tower (tests/data/tower_on_b.toml: 4 m × 12 m,
//! 150 t, FC = 1.35, subsoil B).

#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use rocking_assess::{AgCapacity, Assessment, AssessmentInput, Method};
use std::f64::consts::PI;
use std::path::Path;

const G: f64 = 9.81;

/// The tests' tower with `blocks` (TOML `[[block]]` tables) on it.
fn stacked(blocks: &str) -> AssessmentInput {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    let text = file.replacen("[site]\n", &format!("{blocks}\n[site]\n"), 1);
    assert_ne!(text, file, "tower_on_b.toml has no [site]");
    AssessmentInput::from_toml_str(&text, Path::new("stack.toml")).unwrap()
}

/// As [`stacked`], the verdict carried by the linear kinematic check (`assessment.verdict_method`).
fn stacked_linear(blocks: &str) -> AssessmentInput {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    let text = file.replacen("[site]\n", &format!("{blocks}\n[site]\n"), 1) + "verdict_method = \"linear_kinematic\"\n";
    AssessmentInput::from_toml_str(&text, Path::new("stack.toml")).unwrap()
}

const BELFRY_AND_LANTERN: &str = "[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n\
[[block]]\nname = \"lantern\"\nwidth = 0.8\nheight = 2.0\nmass = 2.0e3\n";

#[test]
fn each_mechanism_is_its_block_with_those_above_it() {
    let input = stacked(BELFRY_AND_LANTERN);
    let done = Assessment::run(&input).unwrap();
    let names: Vec<&str> = done.mechanisms().iter().map(|m| m.name).collect();
    assert_eq!(names, ["tower", "belfry", "lantern"]);

    // By hand. Tower: b = 2; masses 150 t at 6 m, 20 t at 12 + 4 = 16 m, 2 t at
    // 12 + 8 + 1 = 21 m: h = (900 + 320 + 42)/172 = 1262/172 m, M* = 172 t.
    // Belfry: b = 0.8; 20 t at 4 m, 2 t at 8 + 1 = 9 m: h = (80 + 18)/22 = 98/22 m, M* = 22 t.
    // Lantern: b = 0.4, h = 1, M* = 2 t.
    let expected = [(2.0, 1262.0 / 172.0, 1.72e5), (0.8, 98.0 / 22.0, 2.2e4), (0.4, 1.0, 2.0e3)];
    for (m, (b, h, mass)) in done.mechanisms().iter().zip(expected) {
        let c = m.capacity;
        let alpha0 = b / h;
        let a0 = alpha0 * G / 1.35;
        // The capacity is computed from R = √(b² + h²) and α = atan2(b, h), and
        // α0 back from R sin α / R cos α: a few roundings of 1e-16 each.
        let tol = 1e-14;
        assert_relative_eq!(c.alpha0, alpha0, max_relative = tol);
        assert_relative_eq!(c.e_star, 1.0);
        assert_relative_eq!(c.m_star, mass, max_relative = tol);
        assert_relative_eq!(c.a0_star, a0, max_relative = tol);
        assert_relative_eq!(c.d0, b, max_relative = tol);
        assert_relative_eq!(c.d_slv, 0.4 * b, max_relative = tol);
        assert_relative_eq!(c.d_slc, 0.6 * b, max_relative = tol);
        // The linear curve: a*(d_SLV) = 0.6 a0*, a*(d_SLC) = 0.4 a0*.
        assert_relative_eq!(c.t_slv, 1.68 * PI * (0.4 * b / (0.6 * a0)).sqrt(), max_relative = tol);
        assert_relative_eq!(c.t_slc, 1.56 * PI * (0.6 * b / (0.4 * a0)).sqrt(), max_relative = tol);
    }
    // The belfry's numbers written out: α0 = 0.8 · 22 / 98 = 0.179592, a0* = 1.30503 m/s².
    assert_relative_eq!(done.blocks[0].capacity.alpha0, 0.179_592, max_relative = 1e-5);
    assert_relative_eq!(done.blocks[0].capacity.a0_star, 1.305_03, max_relative = 1e-5);

    // Activation on subsoil B, the SLD's F0 = 2.52 (ST = 1): where SS = 1.4 −
    // 0.4 F0 ag is above its cap of 1.2 (ag < 0.2/(0.4 · 2.52) = 0.198 g),
    // ag S = 1.2 ag and the capacity is a0*/(1.2 g): the tower's and the
    // belfry's. The lantern's a0*/(1.2 g) = 0.247 g is beyond: there
    // ag (1.4 − 1.008 ag) = a0*/g, the least root of the quadratic.
    for m in done.mechanisms() {
        let activation = m.checks[0];
        assert_eq!(activation.method, Method::Activation);
        let ratio = m.capacity.a0_star / G;
        let by_hand = if ratio / 1.2 < 0.2 / (0.4 * 2.52) {
            ratio / 1.2
        } else {
            let k = 0.4 * 2.52;
            (1.4 - (1.4f64 * 1.4 - 4.0 * k * ratio).sqrt()) / (2.0 * k)
        };
        assert_eq!(m.name == "lantern", ratio / 1.2 >= 0.198, "{}: the branch", m.name);
        // The root is bisected to 1e-12 g.
        assert!(
            (activation.ag_capacity.value() - by_hand).abs() < 1e-11,
            "{}: {activation:?} against {by_hand}",
            m.name
        );
        assert_relative_eq!(activation.zeta_e, by_hand / 0.062, max_relative = 1e-9);
        // The linear kinematic check: q = 2 times it, against the SLV's 0.155 g.
        assert_relative_eq!(m.checks[1].zeta_e, 2.0 * by_hand / 0.155, max_relative = 1e-9);
    }
    // The numbers written out: the belfry's 0.110859 g, the lantern's 0.260499 g.
    assert_relative_eq!(done.blocks[1].checks[0].ag_capacity.value(), 0.260_499, max_relative = 1e-5);
    assert_relative_eq!(done.blocks[0].checks[0].ag_capacity.value(), 0.110_859, max_relative = 1e-5);

    // The least ζ_E of every check is the belfry's SLV linear kinematic one,
    // 2 · 0.110859 / 0.155 = 1.43044; the verdict, by the most refined method
    // computed, is the least of the mechanisms' non-linear kinematic checks.
    let least = done.completed().into_iter().reduce(|a, c| if c.zeta_e < a.zeta_e { c } else { a }).unwrap();
    assert_eq!(least, done.blocks[0].checks[1]);
    assert_relative_eq!(least.zeta_e, 1.430_44, max_relative = 1e-5);
    let (m, g) = done.governing_mechanism().unwrap();
    assert_eq!(g.method, Method::NonlinearKinematic);
    let least_nonlinear = done
        .completed()
        .into_iter()
        .filter(|c| c.method == Method::NonlinearKinematic)
        .map(|c| c.zeta_e)
        .fold(f64::INFINITY, f64::min);
    assert_eq!(g.zeta_e.to_bits(), least_nonlinear.to_bits());
    assert_eq!(done.governing(), Some(g));
    let json = done.json(&input);
    assert_eq!(json["governing"]["mechanism"], m.name);
    // Named, the linear check carries SLV's verdict: the belfry's 1.43044 again.
    let input = stacked_linear(BELFRY_AND_LANTERN);
    let done = Assessment::run(&input).unwrap();
    let (m, g) = done.governing_mechanism().unwrap();
    assert_eq!((m.name, g.method), ("belfry", Method::LinearKinematic));
    assert_relative_eq!(g.zeta_e, 1.430_44, max_relative = 1e-5);
    let json = done.json(&input);
    assert_eq!(json["governing"]["mechanism"], "belfry");
    assert_eq!(json["governing"]["zeta_E"], g.zeta_e);
    assert_eq!(json["mechanisms"][1]["capacity"]["alpha0"], done.blocks[0].capacity.alpha0);
    // The top-level capacity and checks are the tower's.
    assert_eq!(json["capacity"], json["mechanisms"][0]["capacity"]);
    assert_eq!(json["checks"], json["mechanisms"][0]["checks"]);
}

/// A belfry as wide as the shaft and 1 m tall, of the shaft's density
/// (150 t over 4 × 4 × 12 m³: 12.5 t for 4 × 4 × 1 m³), far too stocky to
/// govern (α0 = 2/0.5 = 4).
const STOCKY: &str = "[[block]]\nname = \"belfry\"\nwidth = 4.0\nheight = 1.0\nmass = 1.25e4\n";

#[test]
fn a_belfry_too_stocky_to_govern_leaves_the_towers_verdict() {
    let input = stacked(STOCKY);
    let done = Assessment::run(&input).unwrap();
    // The belfry never activates within the search: its capacities are lower bounds.
    assert_eq!(done.blocks[0].checks[0].ag_capacity, AgCapacity::AtLeast(2.0));
    // The verdict is the tower's own governing check, to the last bit.
    let (m, g) = done.governing_mechanism().unwrap();
    assert_eq!(m.name, "tower");
    let tower_only = rocking_assess::verdict(&done.checks, None).unwrap().check;
    assert_eq!(g, tower_only);
    assert_eq!(done.json(&input)["governing"]["mechanism"], "tower");

    // The tower with it is one block 4 m × 13 m of 162.5 t: h = 6.5 m exactly
    // ((150 · 6 + 12.5 · 12.5)/162.5 = 1056.25/162.5); its checks are those of
    // that tower given alone, to the rounding of R and α through the stack's
    // widths (a few 1e-16) moved through the bisected roots (1e-12 g).
    let combined = rocking_assess::Capacity::new(1.625e5, 2f64.hypot(6.5), 2f64.atan2(6.5), G, 1.35, rocking_assess::CurveKind::Linear).unwrap();
    assert_relative_eq!(done.capacity.alpha0, 2.0 / 6.5, max_relative = 1e-14);
    assert_relative_eq!(done.capacity.a0_star, combined.a0_star, max_relative = 1e-14);
    assert_relative_eq!(done.capacity.t_slc, combined.t_slc, max_relative = 1e-14);
    let alone = rocking_assess::kinematic_checks(&combined, &input.site, 2.0).unwrap();
    for (stack, one) in done.checks.iter().zip(&alone) {
        assert_relative_eq!(stack.zeta_e, one.zeta_e, max_relative = 1e-9);
    }
}

/// The records of the dynamic checks (the repository's synthetic set).
fn records_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data")
}

/// A small stack on a fixed base: a shaft 1 m × 5 m of 10 t carrying a
/// slender belfry 0.5 m × 2.5 m of 1 t; three synthetic records.
const SMALL: &str = "name = \"small stack\"\n[tower]\nwidth = 1.0\nheight = 5.0\nmass = 1.0e4\n\
[[block]]\nname = \"belfry\"\nwidth = 0.5\nheight = 2.5\nmass = 1.0e3\n";

#[test]
fn the_belfrys_dynamic_check_reads_its_own_rotation() {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    let site = &file[file.find("[site]").unwrap()..];
    let text = format!(
        "{SMALL}{site}records = [\"records/synthetic/kt_01.AT2\", \"records/synthetic/kt_02.AT2\", \"records/synthetic/kt_03.AT2\"]\nfree_after = 3.0\nlambda = {{ from = 0.5, to = 4.0, step = 0.5 }}\naccept_incompatible_set = true\n"
    );
    // The three synthetic records are not compatible with the spectrum
    // (tests/incompatible_set.rs): accepted here, so that their checks carry the verdict.
    let input = AssessmentInput::from_toml_str(&text, &records_dir().join("assess.toml")).unwrap();
    let done = Assessment::run(&input).unwrap();
    let belfry = &done.blocks[0];
    // The belfry alone turns on the shaft: b = 0.25 m, h = 1.25 m.
    let (b, h) = (0.25f64, 1.25f64);
    let (radius, alpha) = (b.hypot(h), b.atan2(h));
    assert_relative_eq!(belfry.capacity.d0, b, max_relative = 1e-14);
    let set = done.set.as_ref().unwrap();
    for (role, check) in belfry.dynamic.iter().enumerate() {
        // Each record at its fitted scale, run again from scenario text (a
        // [ground] record with scale, as `rocking run` reads it): the belfry's
        // largest θ on the shaft, its d* = R (sin α − sin(α − θ)) by hand.
        for ((record, scale), response) in set.records.iter().zip(&check.fitted.scales).zip(&check.at_one.responses) {
            let scenario = format!(
                "{SMALL}[ground]\ntype = \"record\"\nfile = \"{}\"\nscale = {scale}\n[simulation]\nduration = {}\n",
                record.path,
                set_duration(&record.path) + 3.0
            );
            let outcome = rocking_scenario::Scenario::from_toml_str(&scenario, &records_dir().join("run.toml"))
                .unwrap()
                .build()
                .unwrap()
                .run(rocking_scenario::RunOptions::SUMMARY)
                .unwrap();
            let stack = outcome.summary.stack.unwrap();
            let theta = stack.blocks()[0].max_abs_theta;
            let response = response.as_ref().unwrap();
            assert_eq!(response.overturned, stack.overturned_block.is_some(), "{}", record.path);
            if let Some(d) = response.max_displacement {
                // The same run: only the last rounding of the formula may differ.
                assert_relative_eq!(d, radius * (alpha.sin() - (alpha - theta).sin()), max_relative = 1e-12);
            }
            // The tower's response is the shaft's own θ over the whole stack's capacity.
            let tower = done.dynamic[role]
                .at_one
                .responses
                .iter()
                .zip(&set.records)
                .find(|(_, r)| r.path == record.path)
                .unwrap()
                .0;
            if let Some(d) = tower.as_ref().unwrap().max_displacement {
                assert_relative_eq!(d, done.capacity.displacement_at_rotation(stack.tower().max_abs_theta), max_relative = 1e-12);
            }
        }
        // Its verdict: λ ag at the λ that holds.
        let verdict = check.check.unwrap();
        if let Some((lo, _)) = check.bracket {
            assert!((verdict.ag_capacity.value() - lo * verdict.ag).abs() < 1e-15);
        }
    }
    // The governing check is the least ζ_E of both mechanisms' four dynamic
    // ones, the most refined method computed.
    let all: Vec<f64> = done
        .mechanisms()
        .iter()
        .flat_map(|m| m.completed())
        .filter(|c| c.method == Method::NonlinearDynamic)
        .map(|c| c.zeta_e)
        .collect();
    assert_eq!(all.len(), 4);
    // The same number picked, not computed: equal to the bit.
    assert_eq!(
        done.governing().unwrap().zeta_e.to_bits(),
        all.iter().copied().fold(f64::INFINITY, f64::min).to_bits()
    );
    // Here it is the belfry's, dynamic: the slender belfry falls off its shaft
    // under a record the kinematic checks (ζ_E ≥ 1.05) let pass.
    let (m, g) = done.governing_mechanism().unwrap();
    assert_eq!((m.name, g.method), ("belfry", Method::NonlinearDynamic));
}

/// The duration (s) of a record of the synthetic set.
fn set_duration(path: &str) -> f64 {
    let text = std::fs::read_to_string(records_dir().join(path)).unwrap();
    rocking::Record::parse(&text, None, &rocking::CsvOptions::default(), G).unwrap().duration()
}

#[test]
fn an_inventory_names_a_block_that_governs() {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    // The linear kinematic check named to carry the verdict, whose numbers are worked out here.
    let text = file.replacen("[site]\n", &format!("{BELFRY_AND_LANTERN}\n[site]\n"), 1) + "verdict_method = \"linear_kinematic\"\n";
    // Tower a: the file's stack, where the belfry governs (the first test).
    // Tower b: a shaft 1.7 m wide (the belfry's 1.6 m fits on it), α0 =
    // 0.85 · 172/1262 = 0.1158 below the belfry's 0.1796: the tower governs,
    // SLV linear kinematic, ζ_E = 2 (α0 g/1.35)/(1.2 g)/0.155 =
    // 2 · 0.1158/1.62/0.155 = 0.923 (activation at 0.0715 g, on the branch
    // SS = 1.2).
    let towers = "id,name,lon,lat,tower.width\na,a,14.4,41.0,\nb,b,14.4,41.0,1.7\n";
    let inventory = rocking_assess::Inventory::new(&text, Path::new("assess.toml"), towers.as_bytes(), Path::new("towers.csv")).unwrap();
    let header = inventory.header();
    let at = |row: &rocking_scenario::Row, name: &str| row.cells[header.iter().position(|h| h == name).unwrap()].clone();
    let (a, b) = (inventory.row(0), inventory.row(1));
    assert_eq!(at(&a, "governing"), rocking_scenario::Cell::Text("belfry SLV linear_kinematic".into()));
    let rocking_scenario::Cell::Float(zeta) = at(&a, "zeta_E") else {
        panic!("no ζ_E")
    };
    assert_relative_eq!(zeta, 1.430_44, max_relative = 1e-5);
    // The check columns are the tower's: its activation, a0*/(1.2 g) with
    // α0 = 2 · 172/1262.
    let rocking_scenario::Cell::Float(activation) = at(&a, "SLD_activation_ag_capacity_g") else {
        panic!("no activation")
    };
    assert_relative_eq!(activation, 2.0 * 172.0 / 1262.0 / 1.35 / 1.2, max_relative = 1e-9);
    assert_eq!(at(&b, "governing"), rocking_scenario::Cell::Text("SLV linear_kinematic".into()));
    let rocking_scenario::Cell::Float(zeta) = at(&b, "zeta_E") else {
        panic!("no ζ_E")
    };
    assert_relative_eq!(zeta, 2.0 * (0.85 * 172.0 / 1262.0) / 1.62 / 0.155, max_relative = 1e-9);
    assert_relative_eq!(zeta, 0.923, max_relative = 1e-3);
}

/// The example examples/belfry-assess/assess.toml (the S. Anna tower with the
/// belfry of examples/belfry-on-church.toml, at Cervino on the official
/// grid of NTC 2018), its kinematic part (the record set left out: the dynamic checks are
/// those of the command's tests): the belfry's α0 and its SLV linear kinematic
/// ζ_E, and the shaft's α0 under it, by hand.
#[test]
fn the_belfry_example_by_hand() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/belfry-assess/assess.toml");
    let file = std::fs::read_to_string(&path).unwrap();
    let text: String = file.lines().filter(|l| !l.starts_with("records =")).map(|l| format!("{l}\n")).collect();
    assert_eq!(text.lines().count() + 1, file.lines().count(), "the example names its records on one line");
    let input = AssessmentInput::from_toml_str(&text, &path).unwrap();
    let done = Assessment::run(&input).unwrap();
    let belfry = &done.blocks[0];
    assert_eq!(belfry.name, "belfry");

    // The belfry, 3.2 m wide and 4.5 m high, of a given mass (its walls'
    // centre at mid-height): b = 1.6, h = 2.25, α0 = 1.6/2.25 = 0.711111.
    // R and α are rounded on the way: a few 1e-16.
    assert_relative_eq!(belfry.capacity.alpha0, 1.6 / 2.25, max_relative = 1e-14);
    assert_relative_eq!(belfry.capacity.alpha0, 0.711_111, max_relative = 1e-6);
    // The shaft under it: hollow, 4 × 4 m with 0.9 m walls, 14 m of 1800 kg/m³:
    // 1800 · (16 − 2.2²) · 14 = 281 232 kg at 7 m; the belfry's 30 t at 14 +
    // 2.25 m: h = (281 232 · 7 + 30 000 · 16.25)/311 232 = 2 456 124/311 232 m.
    assert_relative_eq!(done.capacity.alpha0, 2.0 * 311_232.0 / 2_456_124.0, max_relative = 1e-14);

    // The site: the official grid at Cervino (14.42 E, 41.04 N), VN 50, CU 1.5,
    // by Allegato A by hand (a Python transcription of the cell search on the
    // decree's lattice, the inverse-distance weights over the nodes 32093,
    // 32094, 32316, 32315 and the log-log in TR; written out in rocking-codes'
    // tests/official_grid.rs): SLD (TR 75.43 years) ag 0.074062 g,
    // F0 2.3774450648274343; SLV (TR 711.8 years) ag 0.17612957238062965 g.
    // Round-off of the weights and the log-log: 1e-12.
    //
    // Its activation, on the SLD spectrum (subsoil B): a0*/g = α0/FC =
    // 0.526749, where SS = 1.4 − 0.4 F0 ag is below 1 (F0 ag = 1.2523 ≥ 1), so
    // SS = 1 and the least root of ag SS(ag) = a0*/g is a0*/g itself (on the
    // branches SS = 1.2 and SS = 1.4 − 0.4 F0 ag, ag SS grows and stays below
    // its value at F0 ag = 1, 1/F0 = 0.4206 < a0*/g). The SLV linear kinematic
    // check: q = 2 times it against the SLV's ag.
    let a0_over_g = 1.6 / 2.25 / 1.35;
    let (sld, slv) = (
        &input.site.spectrum(rocking_assess::Role::Damage),
        &input.site.spectrum(rocking_assess::Role::LifeSafety),
    );
    let rocking_codes::CodeSpectrum::Ntc(sld_ntc) = sld else {
        panic!("an NTC site")
    };
    assert_relative_eq!(sld_ntc.site().f0, 2.3774450648274343, max_relative = 1e-12);
    assert!(sld_ntc.site().f0 * a0_over_g >= 1.0, "the branch SS = 1");
    assert_relative_eq!(slv.ag(), 0.17612957238062965, max_relative = 1e-12);
    let linear = belfry.checks[1];
    assert_eq!((linear.limit_state.to_string().as_str(), linear.method), ("SLV", Method::LinearKinematic));
    // The activation's root is bisected to 1e-12 g; ×2/ag: 1e-11 relative.
    assert_relative_eq!(linear.zeta_e, 2.0 * a0_over_g / 0.17612957238062965, max_relative = 1e-10);
    assert_relative_eq!(linear.zeta_e, 5.98138, max_relative = 1e-5);
    // The belfry is far from governing: the tower's own non-linear kinematic
    // check does (the most refined method computed without records).
    let (m, g) = done.governing_mechanism().unwrap();
    assert_eq!((m.name, g.method), ("tower", Method::NonlinearKinematic));
}
