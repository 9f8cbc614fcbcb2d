//! The outputs of an assessment as data: `assessment.json` as a JSON value and
//! `capacity.csv` as text. The names of the fields are written here once.

use crate::capacity::Capacity;
use crate::check::{governing, Check};
use crate::site::{Role, Site};
use rocking_codes::CodeSpectrum;
use serde_json::{json, Map, Value};

/// The points of the capacity curve in `capacity.csv`.
pub const CAPACITY_POINTS: usize = 201;

/// The header of `capacity.csv`.
pub const CAPACITY_HEADER: [&str; 2] = ["d_star_m", "a_star_m_s2"];

/// The capacity's object of `assessment.json`.
pub fn capacity_json(c: &Capacity) -> Value {
    json!({
        "curve": c.curve.as_str(),
        "confidence_factor": c.confidence_factor,
        "alpha_rad": c.alpha,
        "radius_m": c.radius,
        "alpha0": c.alpha0,
        "e_star": c.e_star,
        "m_star_kg": c.m_star,
        "a0_star_m_s2": c.a0_star,
        "d0_m": c.d0,
        "d_SLV_m": c.d_slv,
        "d_SLC_m": c.d_slc,
        "T_SLV_s": c.t_slv,
        "T_SLC_s": c.t_slc,
    })
}

/// The site object of one limit state's spectrum (5%).
pub fn spectrum_json(spectrum: &CodeSpectrum) -> Value {
    match spectrum {
        CodeSpectrum::Ntc(s) => json!({
            "ag_g": s.site().ag,
            "F0": s.site().f0,
            "Tc_star_s": s.site().tc_star,
            "SS": s.ss(),
            "ST": s.st(),
            "S": s.s(),
            "CC": s.cc(),
            "TB_s": s.tb(),
            "TC_s": s.tc(),
            "TD_s": s.td(),
        }),
        CodeSpectrum::Ec8(s) => {
            let p = s.parameters();
            json!({"ag_g": s.ag(), "S": p.s, "TB_s": p.tb, "TC_s": p.tc, "TD_s": p.td})
        }
    }
}

/// The object of one check.
pub fn check_json(c: &Check) -> Value {
    json!({
        "limit_state": c.limit_state.as_str(),
        "method": c.method.as_str(),
        "demand": c.demand,
        "capacity": c.capacity,
        "unit": c.unit.as_str(),
        "holds": c.holds,
        "ag_g": c.ag,
        "ag_capacity_g": c.ag_capacity.value(),
        "ag_capacity_is_lower_bound": c.ag_capacity.is_lower_bound(),
        "zeta_E": c.zeta_e,
    })
}

/// `assessment.json`: `{"name", "code", "capacity", "sites", "checks", "governing"}`;
/// `extra` adds top-level fields (the dynamic checks' details).
pub fn assessment_json(name: &str, capacity: &Capacity, site: &Site, checks: &[Check], extra: Map<String, Value>) -> Value {
    let mut sites = Map::new();
    for role in Role::ALL {
        sites.insert(site.limit_state(role).as_str().to_string(), spectrum_json(&site.spectrum(role)));
    }
    let mut out = Map::new();
    out.insert("name".into(), json!(name));
    out.insert("code".into(), json!(if site.is_ntc() { "ntc2018" } else { "ec8" }));
    out.insert("capacity".into(), capacity_json(capacity));
    out.insert("sites".into(), Value::Object(sites));
    out.insert("checks".into(), Value::Array(checks.iter().map(check_json).collect()));
    out.insert("governing".into(), governing(checks).map_or(Value::Null, check_json));
    out.extend(extra);
    Value::Object(out)
}

/// `capacity.csv`: `d_star_m,a_star_m_s2`, [`CAPACITY_POINTS`] points of the chosen curve from d = 0 to d0.
pub fn capacity_csv(capacity: &Capacity) -> String {
    let mut out = CAPACITY_HEADER.join(",") + "\n";
    let mut buffer = ryu::Buffer::new();
    for (d, a) in capacity.curve_points(CAPACITY_POINTS) {
        out.push_str(buffer.format(d));
        out.push(',');
        out.push_str(buffer.format(a));
        out.push('\n');
    }
    out
}
