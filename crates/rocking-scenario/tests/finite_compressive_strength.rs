//! `tower.compressive_strength`: the hinge of a masonry of finite strength
//! moves inward to the centroid of the strip along the base's edge that
//! carries the tower's weight at 0.85 f_d (issue 46, item 6). Every number
//! below is worked out by hand from that rule; the tolerances are a few
//! floating-point operations' round-off (1e-12), or the 6 to 7 digits the
//! hand computation kept (1e-6).

use approx::assert_relative_eq;
use rocking::Section;
use rocking_scenario::{hinge_inset, Scenario};
use std::path::Path;

#[test]
fn a_solid_sections_hinge_is_half_the_compressed_strip_in() {
    // N = 1.5e5 kg × 9.81 = 1.4715e6 N; f_d = 2 MPa / 1.35 = 1.481481e6 Pa;
    // the strip's area N / (0.85 f_d) = 1.168544 m², t = area / D = 0.2921360 m, inset t/2.
    let inset = hinge_inset(Section::Solid, 4.0, 4.0, 1.4715e6, 2e6 / 1.35);
    assert_relative_eq!(inset.unwrap_or(f64::NAN), 0.146068, max_relative = 1e-6);
}

#[test]
fn a_hollow_sections_strip_turns_into_the_side_walls() {
    // 6 m × 6 m, walls s = 1 m, f_d = 1 MPa.
    // N = 5e6 N: area 5.882353 m² ≤ D s = 6 m²: the front wall alone, t = 0.9803922 m, inset t/2.
    let front = hinge_inset(Section::Hollow { wall_thickness: 1.0 }, 6.0, 6.0, 5e6, 1e6);
    assert_relative_eq!(front.unwrap_or(f64::NAN), 0.4901961, max_relative = 1e-6);
    // N = 8e6 N: area 9.411765 m²; the front wall's 6 m² at s/2 = 0.5 m, the
    // side walls' 3.411765 m² over t − s = 1.705882 m at (s + t)/2 = 1.852941 m:
    // the centroid (6 × 0.5 + 3.411765 × 1.852941) / 9.411765 = 0.9904412 m.
    let walls = hinge_inset(Section::Hollow { wall_thickness: 1.0 }, 6.0, 6.0, 8e6, 1e6);
    assert_relative_eq!(walls.unwrap_or(f64::NAN), 0.9904412, max_relative = 1e-6);
    // A strip that would pass the middle (t > B/2): none.
    assert_eq!(hinge_inset(Section::Solid, 4.0, 4.0, 1.4715e6, 1e5), None);
}

const TOWER: &str = r#"
[tower]
width = 4.0
height = 12.0
mass = 1.5e5
compressive_strength = 1.0
[ground]
type = "none"
[simulation]
duration = 1.0
g = 9.81
"#;

#[test]
fn a_run_rocks_on_the_inset_hinge() {
    let scenario = Scenario::from_toml_str(TOWER, Path::new("t.toml")).unwrap_or_else(|e| panic!("{e}"));
    let tower = scenario.model().tower().copied().unwrap_or_else(|| panic!("no tower"));
    // In a run f_d = f_m = 1 MPa: t = 1.4715e6 / (0.85e6 × 4) = 0.4327941 m, b' = 2 − t/2, h = 6 m.
    let b: f64 = 2.0 - 1.4715e6 / (0.85e6 * 4.0) / 2.0;
    assert_relative_eq!(tower.alpha(), (b / 6.0).atan(), max_relative = 1e-12);
    assert_relative_eq!(tower.radius(), (b * b + 36.0).sqrt(), max_relative = 1e-12);
    // I_O' = I_G + m R'², I_G = m (B² + H²)/12; Housner's r about the inset pivot.
    let io = 1.5e5 * (16.0 + 144.0) / 12.0 + 1.5e5 * (b * b + 36.0);
    assert_relative_eq!(tower.inertia_pivot(), io, max_relative = 1e-12);
    assert_relative_eq!(tower.restitution(), 1.0 - 2.0 * 1.5e5 * b * b / io, max_relative = 1e-12);
}

#[test]
fn a_strength_that_cannot_carry_the_tower_is_refused_naming_the_key() {
    let weak = TOWER.replace("compressive_strength = 1.0", "compressive_strength = 0.05");
    let e = Scenario::from_toml_str(&weak, Path::new("t.toml")).map(|_| ()).unwrap_err().to_string();
    assert!(
        e.starts_with("t.toml: tower.compressive_strength: 0.05 MPa cannot carry the tower's weight"),
        "{e}"
    );
    let by_radius = "[tower]\nmass = 1.5e5\nradius = 6.3\nalpha = 0.32\ninertia_pivot = 8e6\ncompressive_strength = 2.0\n[ground]\ntype = \"none\"\n[simulation]\nduration = 1.0\n";
    let e = Scenario::from_toml_str(by_radius, Path::new("t.toml")).map(|_| ()).unwrap_err().to_string();
    assert!(
        e.starts_with("t.toml: tower.compressive_strength: does not apply to a tower given by radius and alpha"),
        "{e}"
    );
}
