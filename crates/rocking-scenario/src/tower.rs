//! `[tower]`: the rocking block, by its outer dimensions (`width`, `height`,
//! `mass` or `density`, `section`, …) or by its mechanical properties
//! (`mass`, `inertia_pivot`, `radius`, `alpha`).

use crate::error::{ErrorKind, Fault};
use crate::read::Section;
use rocking::{MassInput, Section as TowerSection, Tower, TowerGeometry};

/// Keys of the geometric description that a tower given by `radius` and `alpha` does not take.
const GEOMETRY_ONLY: &[&str] = &["width", "height", "density", "depth", "section", "wall_thickness", "compressive_strength"];

/// The design compressive stress of the rectangular stress block, as a fraction of `f_d`.
pub const STRESS_BLOCK_FACTOR: f64 = 0.85;

/// The inset (m) of the hinge of a masonry section of finite compressive
/// strength from its base's edge: the centroid of the narrowest strip along
/// the edge whose area carries the weight `n` (N) at `0.85 f_d` (`f_d` in Pa),
/// a rectangular stress block. The strip's area is the section's footprint
/// within `t` of the edge, `depth` long: a solid section's `D t`, so that
/// `t = N / (0.85 f_d D)` and the inset is `t/2`; a hollow one's (wall
/// thickness `s`) the front wall, `D t` while `t ≤ s`, then the front wall
/// and the two side walls it cuts, `D s + 2 s (t − s)`. `None` when the
/// strip would pass the middle of the base (`t > B/2`): the section cannot
/// carry the weight. The project's reading of the Circolare's hinges "moved
/// suitably inward" ("cerniere adeguatamente arretrate").
pub fn hinge_inset(section: TowerSection, width: f64, depth: f64, n: f64, f_d: f64) -> Option<f64> {
    let area = n / (STRESS_BLOCK_FACTOR * f_d);
    let (t, inset) = match section {
        TowerSection::Hollow { wall_thickness: s } if area > depth * s => {
            let sides = area - depth * s;
            let t = s + sides / (2.0 * s);
            (t, (depth * s * s / 2.0 + sides * (s + t) / 2.0) / area)
        }
        _ => {
            let t = area / depth;
            (t, t / 2.0)
        }
    };
    (t.is_finite() && t <= width / 2.0).then_some(inset)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SectionKind {
    Solid,
    Hollow,
}

/// The mass (`mass` or `density`) and the section (`section`,
/// `wall_thickness`) of a body given by its outer dimensions: the tower, or a
/// block on it (`body` names it in errors).
pub(crate) fn mass_and_section(s: &Section<'_>, body: &str) -> Result<(MassInput, TowerSection), Fault> {
    s.exclusive("mass", "density")?;
    let mass = match (s.number("mass")?, s.number("density")?) {
        (Some(m), _) => MassInput::Mass(m),
        (None, Some(rho)) => MassInput::Density(rho),
        (None, None) => {
            return Err(Fault::new(
                s.key("mass"),
                ErrorKind::Missing(format!("required: the {body}'s mass in kg (or its density in kg/m³)")),
            ))
        }
    };
    let kind = s.choice("section", &[("solid", SectionKind::Solid), ("hollow", SectionKind::Hollow)])?;
    let section = match (kind.unwrap_or(SectionKind::Solid), s.number("wall_thickness")?) {
        (SectionKind::Solid, None) => TowerSection::Solid,
        (SectionKind::Solid, Some(_)) => {
            return Err(Fault::new(
                s.key("wall_thickness"),
                ErrorKind::NotApplicable("applies only to section = \"hollow\"".into()),
            ))
        }
        (SectionKind::Hollow, Some(t)) => TowerSection::Hollow { wall_thickness: t },
        (SectionKind::Hollow, None) => {
            return Err(Fault::new(
                s.key("wall_thickness"),
                ErrorKind::Missing("required for section = \"hollow\": the wall thickness in m".into()),
            ))
        }
    };
    Ok((mass, section))
}

/// The tower and the extra points (x, y) in m, tower coordinates, to report.
/// `g` (m/s²) weighs the tower for `compressive_strength`.
pub(crate) fn parse(s: &Section<'_>, g: f64) -> Result<(Tower, Vec<(f64, f64)>), Fault> {
    s.only_scenario_keys()?;
    let restitution = s.number("restitution")?;
    let tower = if s.has("radius") || s.has("alpha") {
        if let Some(k) = GEOMETRY_ONLY.iter().find(|k| s.has(k)) {
            return Err(Fault::new(
                s.key(k),
                ErrorKind::NotApplicable("does not apply to a tower given by radius and alpha (give either width and height, or radius and alpha)".into()),
            ));
        }
        let mass = s.required_number("mass", "the tower's mass in kg")?;
        let inertia = s.required_number("inertia_pivot", "the moment of inertia about a base corner in kg·m², with radius and alpha")?;
        let radius = s.required_number("radius", "R in m, the distance from a base corner to the centre of mass")?;
        let alpha = s.required_number("alpha", "the slenderness angle α = atan(b/h) in rad")?;
        Tower::from_properties(mass, inertia, radius, alpha, restitution)?
    } else {
        let width = s.required_number("width", "the tower's width B in m (or give radius and alpha)")?;
        let height = s.required_number("height", "the tower's height H in m (or give radius and alpha)")?;
        let (mass, section) = mass_and_section(s, "tower")?;
        let depth = s.number("depth")?;
        let tower = Tower::from_geometry(&TowerGeometry {
            width,
            height,
            depth,
            section,
            mass,
            inertia_pivot: s.number("inertia_pivot")?,
            restitution,
        })?;
        match s.number("compressive_strength")? {
            None => tower,
            Some(f_m) => {
                let key = s.key("compressive_strength");
                if !(f_m.is_finite() && f_m > 0.0) {
                    return Err(Fault::invalid(key, format!("must be a number > 0 (MPa), got {f_m}")));
                }
                let n = tower.mass() * g;
                let inset = hinge_inset(section, width, depth.unwrap_or(width), n, f_m * 1e6).ok_or_else(|| {
                    Fault::invalid(
                        key.clone(),
                        format!(
                            "{f_m} MPa cannot carry the tower's weight N = {n:.4e} N: the strip that carries it at 0.85 f_d (f_d = f_m in a run, f_m / FC in an assessment) would pass the middle of the base"
                        ),
                    )
                })?;
                tower.with_pivot_inset(inset, restitution)?
            }
        }
    };
    let points = s.pairs("points")?.unwrap_or_default();
    Ok((tower, points))
}
