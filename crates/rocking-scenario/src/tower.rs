//! `[tower]`: the rocking block, by its outer dimensions (`width`, `height`,
//! `mass` or `density`, `section`, …) or by its mechanical properties
//! (`mass`, `inertia_pivot`, `radius`, `alpha`).

use crate::error::{ErrorKind, Fault};
use crate::read::Section;
use rocking::{MassInput, Section as TowerSection, Tower, TowerGeometry};

/// Keys of the geometric description that a tower given by `radius` and `alpha` does not take.
const GEOMETRY_ONLY: &[&str] = &["width", "height", "density", "depth", "section", "wall_thickness"];

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
pub(crate) fn parse(s: &Section<'_>) -> Result<(Tower, Vec<(f64, f64)>), Fault> {
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
        Tower::from_geometry(&TowerGeometry {
            width,
            height,
            depth: s.number("depth")?,
            section,
            mass,
            inertia_pivot: s.number("inertia_pivot")?,
            restitution,
        })?
    };
    let points = s.pairs("points")?.unwrap_or_default();
    Ok((tower, points))
}
