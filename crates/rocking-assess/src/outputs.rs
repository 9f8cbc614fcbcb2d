//! The outputs of an assessment as data: `assessment.json` as a JSON value and
//! `capacity.csv` as text. The names of the fields are written here once.

use crate::capacity::Capacity;
use crate::check::{verdicts, Check, Method, Verdict};
use crate::dynamic::{DynamicCheck, RecordResponse, RecordSet};
use crate::height::SupportModes;
use crate::site::{Role, Site};
use rocking_codes::SetRule;
use rocking_codes::{CodeSpectrum, LimitState};
use serde_json::{json, Map, Value};

/// The points of the capacity curve in `capacity.csv`.
pub const CAPACITY_POINTS: usize = 201;

/// The header of `capacity.csv`.
pub const CAPACITY_HEADER: [&str; 2] = ["d_star_m", "a_star_m_s2"];

/// A quantity of the capacity, for a reader: its field in `assessment.json`,
/// its symbol and formula (HTML, indices as `<sub>`), its unit and what it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quantity {
    /// Its field in `assessment.json`'s `capacity`.
    pub key: &'static str,
    /// Its symbol, with its formula where it has one (HTML).
    pub symbol_html: &'static str,
    /// Its unit (empty for a number).
    pub unit: &'static str,
    /// What it is.
    pub meaning: &'static str,
}

/// What `d0` is, for the mechanism of the tower (`the tower`) or of a block (`the belfry`):
/// [`D0_MEANING`] with the block named.
pub fn d0_meaning(block: &str) -> String {
    format!("displacement at which a* vanishes: {block} overturns")
}

/// What `d0` is, whichever block the mechanism turns ([`d0_meaning`] names it).
pub const D0_MEANING: &str = "displacement at which a* vanishes: the mechanism's block overturns";

/// The capacity's quantities in the order of report.html and the page (each
/// a field of [`capacity_json`]; the curve's kind aside).
pub const CAPACITY_QUANTITIES: [Quantity; 12] = [
    Quantity {
        key: "alpha_rad",
        symbol_html: "α = atan(b/h)",
        unit: "rad",
        meaning: "slenderness about the base corner (b, h: from it to the centre of mass)",
    },
    Quantity {
        key: "radius_m",
        symbol_html: "R = √(b² + h²)",
        unit: "m",
        meaning: "distance from the base corner to the centre of mass",
    },
    Quantity {
        key: "alpha0",
        symbol_html: "α<sub>0</sub> = b/h",
        unit: "",
        meaning: "activation multiplier (§C8.7.1.2.1.3)",
    },
    Quantity {
        key: "e_star",
        symbol_html: "e*",
        unit: "",
        meaning: "fraction of the mass that takes part: 1, one rigid body",
    },
    Quantity {
        key: "m_star_kg",
        symbol_html: "M* = e* m",
        unit: "kg",
        meaning: "participating mass",
    },
    Quantity {
        key: "confidence_factor",
        symbol_html: "FC",
        unit: "",
        meaning: "confidence factor, dividing the capacity's accelerations",
    },
    Quantity {
        key: "a0_star_m_s2",
        symbol_html: "a<sub>0</sub>* = α<sub>0</sub> g / (e* FC)",
        unit: "m/s²",
        meaning: "spectral acceleration of activation (eq. C8.7.1.8)",
    },
    Quantity {
        key: "d0_m",
        symbol_html: "d<sub>0</sub> = R sin α",
        unit: "m",
        meaning: D0_MEANING,
    },
    Quantity {
        key: "d_SLV_m",
        symbol_html: "d<sub>SLV</sub> = 0.4 d<sub>0</sub>",
        unit: "m",
        meaning: "ultimate displacement at life safety (§C8.7.1.2.1.6)",
    },
    Quantity {
        key: "d_SLC_m",
        symbol_html: "d<sub>SLC</sub> = 0.6 d<sub>0</sub>",
        unit: "m",
        meaning: "ultimate displacement at collapse (§C8.7.1.2.1.6)",
    },
    Quantity {
        key: "T_SLV_s",
        symbol_html: "T<sub>SLV</sub> = 1.68π √(d<sub>SLV</sub>/a*(d<sub>SLV</sub>))",
        unit: "s",
        meaning: "secant period at life safety (eq. C8.7.1.10)",
    },
    Quantity {
        key: "T_SLC_s",
        symbol_html: "T<sub>SLC</sub> = 1.56π √(d<sub>SLC</sub>/a*(d<sub>SLC</sub>))",
        unit: "s",
        meaning: "secant period at collapse (eq. C8.7.1.11)",
    },
];

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
        "level": c.level.as_str(),
        "equation": c.method.equation(c.level, LimitState::EC8.contains(&c.limit_state)),
        "a_Z_g": c.a_z,
    })
}

/// The object of `assessment.json`'s `support`: per limit state, the
/// support's modes at it (`period_s`, `damping`, `participation`,
/// `effective_mass`, a fraction of its mass), its `period_factor` and
/// `damping` as `[assessment.support.<LS>]` gives them (null: its own).
pub fn support_json(site: &Site, support: &SupportModes, values: &dyn Fn(LimitState) -> (f64, Option<f64>)) -> Value {
    let mut out = Map::new();
    for role in Role::ALL {
        let state = site.limit_state(role);
        let (period_factor, damping) = values(state);
        let modes: Vec<Value> = support
            .of(role)
            .iter()
            .map(|m| json!({"period_s": m.period, "damping": m.damping, "participation": m.participation, "effective_mass": m.effective_mass}))
            .collect();
        out.insert(
            state.as_str().to_string(),
            json!({"modes": modes, "period_factor": period_factor, "damping": damping}),
        );
    }
    Value::Object(out)
}

/// The object of the check that carries a verdict: the check's, with
/// `verdict_basis` (`"named"`: the method of `assessment.verdict_method`;
/// `"most_refined"`: the most refined method computed for its limit state).
pub fn verdict_json(v: &Verdict) -> Value {
    let mut out = check_json(&v.check);
    if let Value::Object(map) = &mut out {
        map.insert("verdict_basis".into(), json!(if v.named { "named" } else { "most_refined" }));
    }
    out
}

/// `assessment.json`: `{"name", "code", "capacity", "sites", "checks",
/// "verdicts", "governing", "damage", "dynamic"}`: the kinematic checks, then
/// the dynamic ones (`dynamic`: the set and its checks, if the file has a
/// record set); `verdicts` the check that carries each ultimate limit state's
/// verdict ([`verdicts`], `rule` the method of `assessment.verdict_method` and
/// `assessment.accept_incompatible_set`: a dynamic check on a set outside
/// NTC 2018 §3.2.3.6's band carries none unless accepted),
/// `governing` the one of least ζ_E among them, `damage` the activation check
/// (the damage state), reported beside it.
pub fn assessment_json(
    name: &str,
    capacity: &Capacity,
    site: &Site,
    checks: &[Check],
    dynamic: Option<(&RecordSet, &[DynamicCheck])>,
    rule: (Option<Method>, bool),
) -> Value {
    let (named, accept_incompatible_set) = rule;
    let mut sites = Map::new();
    for role in Role::ALL {
        sites.insert(site.limit_state(role).as_str().to_string(), spectrum_json(&site.spectrum(role)));
    }
    let mut out = Map::new();
    out.insert("name".into(), json!(name));
    out.insert("code".into(), json!(if site.is_ntc() { "ntc2018" } else { "ec8" }));
    out.insert("capacity".into(), capacity_json(capacity));
    out.insert("sites".into(), Value::Object(sites));
    let mut all: Vec<Value> = checks.iter().map(check_json).collect();
    let mut completed: Vec<Check> = checks.to_vec();
    if let Some((_, dynamic)) = dynamic {
        all.extend(dynamic.iter().map(dynamic_check_json));
        completed.extend(dynamic.iter().filter_map(|d| d.verdict_check(accept_incompatible_set)));
    }
    out.insert("checks".into(), Value::Array(all));
    let verdicts = verdicts(&completed, named);
    let governing = verdicts.iter().reduce(|best, v| if v.check.zeta_e < best.check.zeta_e { v } else { best });
    out.insert("verdicts".into(), Value::Array(verdicts.iter().map(verdict_json).collect()));
    out.insert("governing".into(), governing.map_or(Value::Null, verdict_json));
    let damage = checks.iter().find(|c| c.method == Method::Activation);
    out.insert("damage".into(), damage.map_or(Value::Null, check_json));
    out.insert(
        "dynamic".into(),
        dynamic.map_or(Value::Null, |(set, d)| Value::Array(d.iter().map(|c| dynamic_json(set, c)).collect())),
    );
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

/// The header of `records.csv`.
pub const RECORDS_HEADER: [&str; 7] = [
    "limit_state",
    "record",
    "scale",
    "max_control_displacement_m",
    "overturned",
    "max_building_slip_m",
    "error",
];

/// A CSV field: quoted when it holds a comma, a quote or a line break, a
/// text a spreadsheet would read as a formula written as text
/// ([`rocking_scenario::spreadsheet_text`]).
fn field(text: &str) -> String {
    let text = rocking_scenario::spreadsheet_text(text);
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// `x` in the fewest digits that read back to it (`0.155`, `5e-324`, `inf`).
pub(crate) fn number(x: f64) -> String {
    ryu::Buffer::new().format(x).to_string()
}

/// The column of `records.csv` (with blocks on the tower) holding each run's
/// largest seat impulse ratio: above 1 the run breaks the model's assumption
/// that a seated block stays seated through an impact elsewhere.
pub const SEAT_IMPULSE_COLUMN: &str = "max_seat_impulse_ratio";

/// `records.csv`: one row per limit state and record at λ = 1 (the fitted scales):
/// the displacement empty when the tower overturned, the slip empty without a
/// building, `error` the one line of a record that failed to run. With blocks
/// on the tower (`blocks`: each block's name and dynamic checks, in the order
/// of `checks`), each adds `<name>_max_control_displacement_m` (its own θ's
/// d*, empty when its mechanism collapsed) and `<name>_overturned` (it fell,
/// or a block under it did) after `max_building_slip_m`, and the run's
/// [`SEAT_IMPULSE_COLUMN`] after them.
pub fn records_csv(set: &RecordSet, checks: &[DynamicCheck], blocks: &[(&str, &[DynamicCheck])]) -> String {
    let mut header: Vec<String> = RECORDS_HEADER[..RECORDS_HEADER.len() - 1].iter().map(|h| h.to_string()).collect();
    for (name, _) in blocks {
        header.push(format!("{name}_max_control_displacement_m"));
        header.push(format!("{name}_overturned"));
    }
    if !blocks.is_empty() {
        header.push(SEAT_IMPULSE_COLUMN.into());
    }
    header.push("error".into());
    let mut out = header.join(",") + "\n";
    for (c, check) in checks.iter().enumerate() {
        for (i, ((record, scale), response)) in set.records.iter().zip(&check.fitted.scales).zip(&check.at_one.responses).enumerate() {
            let mut row = vec![check.limit_state.as_str().to_string(), field(&record.path), number(*scale)];
            let push = |row: &mut Vec<String>, response: &Result<RecordResponse, String>, slip: bool| match response {
                Ok(r) => {
                    row.push(r.max_displacement.map(number).unwrap_or_default());
                    row.push(r.overturned.to_string());
                    if slip {
                        row.push(r.max_slip.map(number).unwrap_or_default());
                    }
                }
                Err(_) => row.extend(std::iter::repeat_n(String::new(), if slip { 3 } else { 2 })),
            };
            push(&mut row, response, true);
            for (_, block) in blocks {
                push(&mut row, &block[c].at_one.responses[i], false);
            }
            if !blocks.is_empty() {
                row.push(response.as_ref().ok().and_then(|r| r.max_seat_impulse_ratio).map(number).unwrap_or_default());
            }
            row.push(response.as_ref().err().map(|e| field(e)).unwrap_or_default());
            out.push_str(&row.join(","));
            out.push('\n');
        }
    }
    out
}

/// `spectra.csv`: `period_s`, then for each limit state its code spectrum
/// (`Se_<LS>_g`, 5%), with a `[support]` the code's floor spectrum of its
/// top (`SeZ_<LS>_g`, 5%) and the mean computed on it with the scaled
/// records through the support alone (`PSAZ_<LS>_mean_g`), each fitted record's scaled spectrum
/// (`PSA_<LS>_<record>_g`) and their mean (`PSA_<LS>_mean_g`).
pub fn spectra_csv(set: &RecordSet, checks: &[DynamicCheck]) -> String {
    let mut header = vec!["period_s".to_string()];
    let mut columns: Vec<Vec<f64>> = vec![set.periods.clone()];
    for c in checks {
        header.push(format!("Se_{}_g", c.limit_state));
        columns.push(c.target_g.clone());
        if let Some(floor) = &c.floor_g {
            header.push(format!("SeZ_{}_g", c.limit_state));
            columns.push(floor.clone());
        }
        if let Some(mean) = &c.floor_mean_g {
            header.push(format!("PSAZ_{}_mean_g", c.limit_state));
            columns.push(mean.clone());
        }
        for (record, scale) in set.records.iter().zip(&c.fitted.scales) {
            header.push(field(&format!("PSA_{}_{}_g", c.limit_state, record.name)));
            columns.push(record.psa_g.iter().map(|a| scale * a).collect());
        }
        header.push(format!("PSA_{}_mean_g", c.limit_state));
        columns.push(c.fitted.mean.clone());
    }
    let mut out = header.join(",") + "\n";
    for k in 0..set.periods.len() {
        let row: Vec<String> = columns.iter().map(|c| number(c[k])).collect();
        out.push_str(&row.join(","));
        out.push('\n');
    }
    out
}

/// The details of one dynamic check in `assessment.json` (`"dynamic"`): the
/// fit (scales, compatibility, rule, range), the λ bracket, the scan, and the
/// error when it could not be completed.
pub fn dynamic_json(set: &RecordSet, c: &DynamicCheck) -> Value {
    json!({
        "limit_state": c.limit_state.as_str(),
        "records": set.records.iter().map(|r| r.path.as_str()).collect::<Vec<_>>(),
        "scales": c.fitted.scales,
        "period_range_s": [set.range.0, set.range.1],
        "compatibility": {
            "least_ratio": c.fitted.compatibility.least_ratio,
            "greatest_ratio": c.fitted.compatibility.greatest_ratio,
            "holds": c.fitted.compatibility.holds,
        },
        "response_rule": match c.fitted.rule { SetRule::Mean => "mean", SetRule::Largest => "largest" },
        "lambda_holds": c.bracket.map(|b| b.0),
        "lambda_fails": c.bracket.map(|b| b.1),
        "scan": c.scan.iter().map(|p| json!({"lambda": p.lambda, "response_m": p.combined, "holds": p.holds})).collect::<Vec<_>>(),
        "completed": c.check.is_some(),
        "valid": c.is_valid(),
        "error": c.error,
    })
}

/// The object of a dynamic check in `assessment.json`'s `"checks"`: the check's,
/// or, when a record failed, the limit state and method with `"completed": false` and the error.
pub fn dynamic_check_json(c: &DynamicCheck) -> Value {
    match &c.check {
        Some(check) => check_json(check),
        None => json!({
            "limit_state": c.limit_state.as_str(),
            "method": Method::NonlinearDynamic.as_str(),
            "completed": false,
            "error": c.error,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::{capacity_json, CAPACITY_QUANTITIES};
    use crate::{Capacity, CurveKind};

    /// The described quantities are the capacity's numeric fields of
    /// `assessment.json`, each once: none missing from the report and the
    /// page, none described that the file lacks.
    #[test]
    fn the_capacitys_quantities_are_its_numeric_fields() {
        let capacity = Capacity::new(1.5e5, 40f64.sqrt(), (1.0f64 / 3.0).atan(), 9.81, 1.35, CurveKind::Linear).unwrap_or_else(|e| panic!("{e}"));
        let json = capacity_json(&capacity);
        let mut numeric: Vec<&str> = json
            .as_object()
            .into_iter()
            .flatten()
            .filter(|(_, v)| v.is_number())
            .map(|(k, _)| k.as_str())
            .collect();
        let mut described: Vec<&str> = CAPACITY_QUANTITIES.iter().map(|q| q.key).collect();
        numeric.sort_unstable();
        described.sort_unstable();
        assert_eq!(described, numeric);
    }
}
