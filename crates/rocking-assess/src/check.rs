//! The verdict of one check: its demand against its capacity at the site's
//! `ag`, the least `ag` at which it stops holding and the ratio ζ_E.

use crate::search::AgCapacity;
use rocking_codes::LimitState;
use std::fmt;

/// The method of a check (Circolare 2019 §C8.7.1.2.1.5–C8.7.1.2.1.9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Method {
    /// The activation of the mechanism (damage limit state).
    Activation,
    /// The linear kinematic analysis with the behaviour factor q (§C8.7.1.2.1.7).
    LinearKinematic,
    /// The non-linear kinematic analysis, the displacement spectrum (§C8.7.1.2.1.8).
    NonlinearKinematic,
    /// The non-linear dynamic analysis, records run through the model (§C8.7.1.2.1.9).
    NonlinearDynamic,
}

impl Method {
    /// Its name in the outputs: `activation`, `linear_kinematic`, `nonlinear_kinematic`, `nonlinear_dynamic`.
    pub fn as_str(self) -> &'static str {
        match self {
            Method::Activation => "activation",
            Method::LinearKinematic => "linear_kinematic",
            Method::NonlinearKinematic => "nonlinear_kinematic",
            Method::NonlinearDynamic => "nonlinear_dynamic",
        }
    }
}

/// What a check is, for a reader: the words of the report and of the page.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MethodText {
    /// Its name in words: `activation`, `linear kinematic`, `non-linear kinematic`, `non-linear dynamic`.
    pub name: &'static str,
    /// When it stops holding, in HTML (indices as `<sub>`), with the Circolare's section.
    pub formula_html: String,
}

impl Method {
    /// Every method, in the order of the checks.
    pub const ALL: [Method; 4] = [
        Method::Activation,
        Method::LinearKinematic,
        Method::NonlinearKinematic,
        Method::NonlinearDynamic,
    ];

    /// Its name and formula, `q` the behaviour factor of the linear kinematic check.
    pub fn text(self, q: f64) -> MethodText {
        let (name, formula_html) = match self {
            Method::Activation => (
                "activation",
                "a<sub>g</sub> S(a<sub>g</sub>) ≥ a<sub>0</sub>* activates (Circolare 2019 eq. C8.7.1.8)".to_string(),
            ),
            Method::LinearKinematic => (
                "linear kinematic",
                format!("a<sub>g</sub> &gt; q · a<sub>g,capacity</sub>(activation), q = {q} (§C8.7.1.2.1.7)"),
            ),
            Method::NonlinearKinematic => (
                "non-linear kinematic",
                "max<sub>T ≤ T<sub>LS</sub></sub> S<sub>De</sub>(T; ξ) &gt; d<sub>LS</sub>, ξ = 8% (SLV, T<sub>SLV</sub> of eq. C8.7.1.10), 10% (SLC, T<sub>SLC</sub> of eq. C8.7.1.11) (§C8.7.1.2.1.8)".to_string(),
            ),
            Method::NonlinearDynamic => (
                "non-linear dynamic",
                "records run through the model: none beyond d<sub>0</sub> (§C8.7.1.2.1.9), mean (largest with fewer than 7, NTC 2018 §7.3.5) ≤ d<sub>LS</sub>".to_string(),
            ),
        };
        MethodText { name, formula_html }
    }
}

impl Method {
    /// The equation a check of this method at `level` takes, with its source
    /// (`ec8`: EN 1998-1's spectra): `C8.7.1.8 (Circolare 2019)` at ground
    /// level, `[C8.7.1.8] with [C7.2.8] (Circolare 2019)` at height, ….
    pub fn equation(self, level: Level, ec8: bool) -> &'static str {
        match (self, level, ec8) {
            (Method::Activation, Level::Ground, _) => "C8.7.1.8 (Circolare 2019), the ground's spectrum",
            (Method::Activation, Level::Support, false) => "C8.7.1.8 with [C7.2.7], [C7.2.8] (Circolare 2019): the peak floor acceleration",
            (Method::Activation, Level::Support, true) => "EN 1998-1 eq. (4.25) at the support's top, T_a = 0: 2.5 α S",
            (Method::LinearKinematic, _, _) => "§C8.7.1.2.1.7 (Circolare 2019): q times the activation's a_g",
            (Method::NonlinearKinematic, Level::Ground, _) => "C8.7.1.12 (Circolare 2019), the ground's displacement spectrum",
            (Method::NonlinearKinematic, Level::Support, false) => {
                "C8.7.1.12 with [C7.2.5], [C7.2.6] (Circolare 2019): the floor spectrum, bounded beyond b T_1"
            }
            (Method::NonlinearKinematic, Level::Support, true) => "EN 1998-1 eq. (4.25) at the support's top, at the secant period",
            (Method::NonlinearDynamic, _, _) => "§C8.7.1.2.1.9 (Circolare 2019): the records through the model",
        }
    }

    /// Its name and formula at `level` (`ec8`: EN 1998-1's spectra): at
    /// ground level [`Method::text`]'s, at height the floor spectrum's.
    pub fn text_at(self, q: f64, level: Level, ec8: bool) -> MethodText {
        let ground = self.text(q);
        let formula_html = match (self, level, ec8) {
            (_, Level::Ground, _) | (Method::NonlinearDynamic, _, _) => return ground,
            (Method::Activation, _, false) => {
                "a<sub>Z</sub>(a<sub>g</sub>) ≥ a<sub>0</sub>* activates, a<sub>Z</sub> = √Σ a<sub>Z,k</sub>², a<sub>Z,k</sub> = S<sub>e</sub>(T<sub>k</sub>, ξ<sub>k</sub>) |Γ<sub>k</sub>| √(1 + 0.0004 ξ<sub>k</sub>²) the support top's peak floor acceleration (Circolare 2019 eq. C8.7.1.8 with [C7.2.7], [C7.2.8])".to_string()
            }
            (Method::Activation, _, true) => {
                "S<sub>a</sub>(0) = 2.5 α S ≥ a<sub>0</sub>*/g activates (EN 1998-1 eq. 4.25 at the support's top, z/H = 1)".to_string()
            }
            (Method::LinearKinematic, _, _) => format!(
                "a<sub>g</sub> &gt; q · a<sub>g,capacity</sub>(activation at height), q = {q} (§C8.7.1.2.1.7)"
            ),
            (Method::NonlinearKinematic, _, false) => {
                "S<sub>eZ</sub>(T<sub>LS</sub>; ξ) T<sub>LS</sub>²/4π², and not less than S<sub>eZ</sub>(T<sub>1</sub>; ξ) (b T<sub>1</sub>)²/4π² when T<sub>LS</sub> &gt; b T<sub>1</sub>, &gt; d<sub>LS</sub>, ξ = 8% (SLV), 10% (SLC) (eq. C8.7.1.12 with the floor spectrum [C7.2.5], [C7.2.6])".to_string()
            }
            (Method::NonlinearKinematic, _, true) => {
                "S<sub>a</sub>(T<sub>LS</sub>) g T<sub>LS</sub>²/4π² &gt; d<sub>LS</sub> (EN 1998-1 eq. 4.25 at the support's top, at the secant period)".to_string()
            }
        };
        MethodText {
            name: ground.name,
            formula_html,
        }
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// What a demand and a capacity are measured in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Unit {
    /// A spectral acceleration (m/s²).
    Acceleration,
    /// A spectral displacement (m).
    Displacement,
    /// A ground acceleration `ag` (g).
    GroundAcceleration,
}

impl Unit {
    /// `m/s2`, `m` or `g`.
    pub fn as_str(self) -> &'static str {
        match self {
            Unit::Acceleration => "m/s2",
            Unit::Displacement => "m",
            Unit::GroundAcceleration => "g",
        }
    }
}

/// Where a check takes the mechanism to stand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Level {
    /// At ground level, on a rigid support: the ground's spectra (or records).
    Ground,
    /// On the elastic support's top: the floor spectrum (Circolare 2019 §C7.2.3).
    Support,
}

impl Level {
    /// Its name in the outputs: `ground` or `support`.
    pub fn as_str(self) -> &'static str {
        match self {
            Level::Ground => "ground",
            Level::Support => "support",
        }
    }
}

/// The ratio `ζ_E = a_g,capacity / a_g` of a limit state (Circolare 2019 §C8.7.1.2.1.5
/// and the Civil Protection's ranking of buildings): the check holds when ζ_E ≥ 1.
pub fn acceleration_ratio(ag_capacity: f64, ag: f64) -> f64 {
    ag_capacity / ag
}

/// One check of one limit state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// The limit state.
    pub limit_state: LimitState,
    /// The method.
    pub method: Method,
    /// The demand at the limit state's `ag`, in `unit`.
    pub demand: f64,
    /// The capacity, in `unit`.
    pub capacity: f64,
    /// The unit of demand and capacity.
    pub unit: Unit,
    /// The limit state's `ag` (g).
    pub ag: f64,
    /// The least `ag` (g) at which the check stops holding.
    pub ag_capacity: AgCapacity,
    /// `ζ_E = a_g,capacity / a_g` (a lower bound when `ag_capacity` is).
    pub zeta_e: f64,
    /// Whether it holds: ζ_E ≥ 1.
    pub holds: bool,
    /// Where it takes the mechanism to stand.
    pub level: Level,
    /// The peak floor acceleration `a_Z` (g) of the support's top at the limit
    /// state's `a_g` (a check at height); `None` at ground level.
    pub a_z: Option<f64>,
}

impl Check {
    /// A check from its demand and capacity at the site's `ag` and its `ag`
    /// capacity. It holds when ζ_E ≥ 1, and whenever the capacity is only a
    /// lower bound ([`AgCapacity::AtLeast`]): no failure was found at any `ag`
    /// searched, the site's included (the dynamic scan bisects up to λ = 1
    /// when the set fails at the site), so `ζ_E ≥ …` is a bound that holds,
    /// never a failure.
    pub fn new(limit_state: LimitState, method: Method, unit: Unit, demand: f64, capacity: f64, ag: f64, ag_capacity: AgCapacity) -> Self {
        let zeta_e = acceleration_ratio(ag_capacity.value(), ag);
        Self {
            limit_state,
            method,
            demand,
            capacity,
            unit,
            ag,
            ag_capacity,
            zeta_e,
            holds: zeta_e >= 1.0 || ag_capacity.is_lower_bound(),
            level: Level::Ground,
            a_z: None,
        }
    }

    /// The check at `level`, with the peak floor acceleration `a_z` (g) of a check at height.
    pub fn at(self, level: Level, a_z: Option<f64>) -> Self {
        Self { level, a_z, ..self }
    }
}

impl Check {
    /// Whether its numbers (demand, capacity, `ag`, `a_g,capacity`, ζ_E) are all finite.
    pub fn is_finite(&self) -> bool {
        [self.demand, self.capacity, self.ag, self.ag_capacity.value(), self.zeta_e]
            .iter()
            .all(|x| x.is_finite())
    }
}

/// The check of least ζ_E whatever its method (the first such in order),
/// `None` for no checks: information, not the verdict ([`verdict`]).
pub fn least_zeta_e(checks: &[Check]) -> Option<&Check> {
    checks.iter().reduce(|best, c| if c.zeta_e < best.zeta_e { c } else { best })
}

impl Method {
    /// How far the method refines the analysis of a mechanism, for the
    /// verdict: the non-linear dynamic check (records run through the model,
    /// §C8.7.1.2.1.9) above the non-linear kinematic one (the displacement
    /// spectrum, §C8.7.1.2.1.8) above the linear one (q times the activation,
    /// §C8.7.1.2.1.7), the Circolare's alternatives for the ultimate limit
    /// states; `None` for the activation, the damage state's check, which
    /// carries no verdict of SLV or SLC.
    pub fn refinement(self) -> Option<u8> {
        match self {
            Method::Activation => None,
            Method::LinearKinematic => Some(1),
            Method::NonlinearKinematic => Some(2),
            Method::NonlinearDynamic => Some(3),
        }
    }
}

/// The check that carries the verdict of one limit state, and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// The check.
    pub check: Check,
    /// Whether its method is the one the file names (`assessment.verdict_method`);
    /// else it is the most refined method computed for its limit state.
    pub named: bool,
}

/// The verdict of each ultimate limit state of `checks` (SLV, then SLC; EN
/// 1998-3's SD, NC), in the order they first appear: the check of the method
/// `named` when the limit state has one, else that of the most refined method
/// computed ([`Method::refinement`]). The activation check (SLD) gives none: it
/// is reported beside the verdict, not mixed into it; the other checks of the
/// limit state are information.
pub fn verdicts(checks: &[Check], named: Option<Method>) -> Vec<Verdict> {
    let mut states: Vec<LimitState> = Vec::new();
    for c in checks.iter().filter(|c| c.method.refinement().is_some()) {
        if !states.contains(&c.limit_state) {
            states.push(c.limit_state);
        }
    }
    states
        .into_iter()
        .filter_map(|state| {
            let of_state = || checks.iter().filter(move |c| c.limit_state == state);
            if let Some(c) = named.and_then(|m| of_state().find(|c| c.method == m)) {
                return Some(Verdict { check: *c, named: true });
            }
            // The first of the most refined: a tie of refinement does not occur
            // (one check per method and limit state).
            of_state()
                .filter(|c| c.method.refinement().is_some())
                .reduce(|best, c| if c.method.refinement() > best.method.refinement() { c } else { best })
                .map(|c| Verdict { check: *c, named: false })
        })
        .collect()
}

/// The verdict of a mechanism: the least ζ_E of its limit states' [`verdicts`]
/// (the first such, life safety before collapse), `None` without one.
pub fn verdict(checks: &[Check], named: Option<Method>) -> Option<Verdict> {
    verdicts(checks, named)
        .into_iter()
        .reduce(|best, v| if v.check.zeta_e < best.check.zeta_e { v } else { best })
}
