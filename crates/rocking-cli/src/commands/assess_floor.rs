//! The parts of `report.html` about where the mechanisms stand: at ground
//! level on a rigid support, or on an elastic support's top (`[support]`),
//! with the support's modes at each limit state and, per limit state, the
//! code's floor spectrum beside the ground's.

use super::assess_report::{esc, scalable};
use crate::format::sig;
use crate::plot::{spectra_svg, Curve, Ink, SpectraFigure};
use rocking_assess::{
    floor_spectrum_at, kinematic_checks, peak_floor_acceleration, verdict, Assessment, AssessmentInput, Check, DynamicCheck, Method, RecordSet, Role, Verdict,
};
use rocking_codes::DEFAULT_PERIODS;
use std::fmt::Write;

/// The sentence of the report's opening note on where the mechanisms stand.
pub fn level_sentence(input: &AssessmentInput) -> String {
    match &input.file.support {
        None => "Every mechanism is taken at ground level on a rigid support: the building under the tower is rigid, so that the springing level moves with the ground when the building does not slide (the file has no <code>[support]</code>; a tower standing on an elastic church, or a belfry on its shaft, is a mechanism above ground, whose checks take the floor spectrum of the level it stands on: see section 2).".to_string(),
        Some(_) => format!(
            "Every mechanism stands on the top of an elastic support (the file's <code>[support]</code>: the church, or the shaft): its kinematic checks take the floor spectrum of the support's top ({}), each limit state with the support's own period and damping or those of <code>[assessment.support.&lt;LS&gt;]</code> (section 2). The top is taken not to rotate. The non-linear dynamic checks run the records through a model without the support (the coupled model is not in the engine yet): they are at ground level, not at height, shown as information and kept out of the verdict.",
            if input.site.is_ntc() {
                "Circolare 2019 §C8.7.1.2.1.4–8 with eqs. [C7.2.5]–[C7.2.8] of §C7.2.3"
            } else {
                "EN 1998-1 §4.3.5.2, eq. (4.25) with z/H = 1"
            }
        ),
    }
}

/// The support's part of section 2: its modes at each limit state, the peak
/// floor acceleration at the limit state's `a_g`, and per limit state the
/// code's floor spectrum beside the ground's. Empty without a support.
pub fn support_html(input: &AssessmentInput) -> anyhow::Result<String> {
    let Some(support) = &input.support else {
        return Ok(String::new());
    };
    let mut out = String::new();
    let ntc = input.site.is_ntc();
    let _ = writeln!(
        out,
        "<h3>The elastic support</h3><p>Its modes at each limit state (periods T<sub>k</sub>, damping ratios ξ<sub>k</sub>, participation Γ<sub>k</sub> with the shape 1 where the tower stands, effective mass as a fraction of the support's {} kg), and the peak floor acceleration a<sub>Z</sub> of its top at the limit state's a<sub>g</sub>{}.</p>",
        sig(input.file.support.as_ref().map_or(0.0, |s| s.mass), 4),
        if ntc {
            ": a<sub>Z,k</sub> = S<sub>e</sub>(T<sub>k</sub>, ξ<sub>k</sub>) |Γ<sub>k</sub>| √(1 + 0.0004 ξ<sub>k</sub>²) ([C7.2.7], ξ<sub>k</sub> in percent), a<sub>Z</sub> = √Σ a<sub>Z,k</sub>² ([C7.2.8])"
        } else {
            ": S<sub>a</sub>(0) = 2.5 α S (EN 1998-1 eq. 4.25 at z/H = 1)"
        }
    );
    let _ = writeln!(
        out,
        "<table><tr><th>limit state</th><th>period factor</th><th>mode</th><th>T<sub>k</sub> (s)</th><th>ξ<sub>k</sub></th><th>Γ<sub>k</sub></th><th>m<sub>eff,k</sub>/m<sub>s</sub></th><th>a<sub>Z</sub> (g)</th></tr>"
    );
    for role in Role::ALL {
        let state = input.site.limit_state(role);
        let spectrum = input.site.spectrum(role);
        let modes = support.of(role);
        let a_z = peak_floor_acceleration(&spectrum, modes)?;
        let factor = input.file.support_state(state).period_factor;
        for (k, m) in modes.iter().enumerate() {
            let head = if k == 0 {
                format!(
                    "<td rowspan=\"{n}\">{state}</td><td rowspan=\"{n}\" class=\"n\">{}</td>",
                    sig(factor, 3),
                    n = modes.len()
                )
            } else {
                String::new()
            };
            let tail = if k == 0 {
                format!("<td rowspan=\"{}\" class=\"n\">{}</td>", modes.len(), sig(a_z, 4))
            } else {
                String::new()
            };
            let _ = writeln!(
                out,
                "<tr>{head}<td>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td>{tail}</tr>",
                k + 1,
                sig(m.period, 4),
                sig(m.damping, 3),
                sig(m.participation, 4),
                sig(m.effective_mass, 4)
            );
        }
    }
    let _ = writeln!(out, "</table>");
    let _ = writeln!(
        out,
        "<p class=\"note\">{}</p>",
        if ntc {
            "The floor spectrum of each mode is [C7.2.6] with A<sub>k</sub> = 1.1 ξ<sub>k</sub><sup>−1/2</sup> η(ξ), a = 0.8, b = 1.1, ξ<sub>k</sub> read as a fraction of critical (read in percent, A<sub>k</sub> would be 0.49 at 5% and the plateau would fall below the floor's own peak acceleration, against Table C7.2.II's a<sub>p</sub> = 5 and the formulation's source, Degli Abbati, Cattari and Lagomarsino 2018); the modes combine by [C7.2.5], and beyond T<sub>1</sub> the floor spectrum is not less than the ground's. The code's floor spectrum leaves out the interaction of §C8.7.1.2.1.4 (the mechanism's mass and rocking acting back on the support)."
        } else {
            "EN 1998-1 gives eq. (4.25) for the acceleration of an element of period T<sub>a</sub>; its use at the mechanism's secant period in the non-linear kinematic check is this tool's choice."
        }
    );
    let periods = DEFAULT_PERIODS.periods()?;
    for role in Role::ALL {
        let state = input.site.limit_state(role);
        let spectrum = input.site.spectrum(role);
        let modes = support.of(role);
        let ground: Vec<(f64, f64)> = periods.iter().map(|&t| (t, spectrum.se(t))).collect();
        let floor = periods
            .iter()
            .map(|&t| Ok((t, floor_spectrum_at(&spectrum, modes, t, 5.0)?)))
            .collect::<anyhow::Result<Vec<(f64, f64)>>>()?;
        let figure = SpectraFigure {
            title: format!("{state}: the floor spectrum of the support's top beside the ground's"),
            subtitle: format!(
                "5% damping; a_g = {} g; the support's first period {} s",
                sig(spectrum.ag(), 4),
                sig(rocking_assess::first_period(modes), 4)
            ),
            y_label: "spectral acceleration (g)".into(),
            curves: vec![
                Curve {
                    label: Some(format!("{state} ground spectrum S_e")),
                    ink: Ink::Target,
                    width: 3,
                    dashed: true,
                    points: ground,
                },
                Curve {
                    label: Some(format!("{state} floor spectrum {}", if ntc { "S_eZ [C7.2.5]" } else { "S_a (EN 1998-1 4.25)" })),
                    ink: Ink::Mean,
                    width: 3,
                    dashed: false,
                    points: floor,
                },
            ],
            band: None,
            range: None,
        };
        let _ = writeln!(
            out,
            "<figure>{}<figcaption>{}: the code's floor spectrum of the support's top (solid) and the ground's spectrum (dashed) at 5% damping.</figcaption></figure>",
            scalable(spectra_svg(&figure)?, (1000, 680)),
            esc(state.as_str())
        );
    }
    Ok(out)
}

/// The note of section 4 when the mechanisms stand on a support: the runs
/// leave it out. Empty without a support.
pub fn dynamic_note(input: &AssessmentInput) -> String {
    if input.file.support.is_none() {
        return String::new();
    }
    "<p class=\"fails\">At ground level, not at height: these runs leave out the elastic support under the tower (the coupled model of the tower on its support is not in the engine yet), so that they show the mechanism on a rigid support. They are information only and carry no verdict; the verdict is the kinematic checks' at height (section 3).</p>\
     <p class=\"note\">Each figure of the fitted set also draws two floor spectra of the support's top at 5%: the code's (S<sub>eZ</sub>, [C7.2.5]) and the mean computed with each scaled record through the support alone (its modes linear oscillators, the top's absolute acceleration a<sub>g</sub> + Σ Γ<sub>k</sub> ÿ<sub>k</sub>). They differ because the code's is an envelope for any record and any support, and because neither holds the interaction of §C8.7.1.2.1.4, the tower's mass and rocking acting back on the support; the verdict uses the code's.</p>".to_string()
}

/// The verdict of the same mechanisms on a rigid support, for comparison
/// (with a `[support]`): each mechanism's kinematic checks at ground level
/// and its dynamic checks (which ran at ground level), the verdict taken as
/// without a support; and which of the two to report. Empty without a support.
pub fn rigid_comparison(input: &AssessmentInput, done: &Assessment) -> anyhow::Result<String> {
    if input.file.support.is_none() {
        return Ok(String::new());
    }
    let q = input.file.q;
    let mut rigid: Option<(String, Verdict)> = None;
    let mut damage: Option<(String, Check)> = None;
    for m in done.mechanisms() {
        let mut candidates = kinematic_checks(m.capacity, &input.site, q)?;
        if let Some(c) = candidates.iter().find(|c| c.method == Method::Activation) {
            if damage.as_ref().is_none_or(|(_, d)| c.zeta_e < d.zeta_e) {
                damage = Some((m.name.to_string(), *c));
            }
        }
        candidates.extend(
            m.dynamic
                .iter()
                .filter_map(|d| d.check.filter(|_| done.accept_incompatible_set || d.is_valid())),
        );
        if let Some(v) = verdict(&candidates, done.verdict_method) {
            if rigid.as_ref().is_none_or(|(_, r)| v.check.zeta_e < r.check.zeta_e) {
                rigid = Some((m.name.to_string(), v));
            }
        }
    }
    let line = |name: &str, c: &Check| {
        format!(
            "{}{} {}, ζ<sub>E</sub> = {}{} ({})",
            if done.mechanisms().len() > 1 {
                format!("{}, ", esc(name))
            } else {
                String::new()
            },
            c.limit_state,
            c.method.text(q).name,
            if c.ag_capacity.is_lower_bound() { "≥ " } else { "" },
            sig(c.zeta_e, 3),
            if c.holds { "holds" } else { "fails" }
        )
    };
    let mut out = String::from("<h3>The same tower on a rigid church, for comparison</h3>");
    if let (Some((name, v)), Some((dname, d))) = (&rigid, &damage) {
        let _ = write!(
            out,
            "<p>Taken at ground level on a rigid support (the file without its <code>[support]</code>), the verdict would be {}, and the damage state's {}.</p>",
            line(name, &v.check),
            line(dname, d)
        );
    }
    let _ = write!(
        out,
        "<p class=\"note\">Report the verdict at height, above: the tower stands on the church, and the church's own period on the plateau of the spectra makes its top move more than the ground (a<sub>Z</sub> in section 2), which the rigid support leaves out. The rigid-support verdict is the assessment of a tower at ground level; for a tower on an elastic church it is not on the safe side. Where the two differ, the difference is the church's amplification; the linear check, q times the activation, carries it in full, while the non-linear kinematic check, at secant periods far beyond the church's, is moved little by it.</p>"
    );
    Ok(out)
}

/// The floor spectra of a dynamic check's figure, with a `[support]`: the
/// code's (`S_eZ`, 5%) and the mean computed on the support's top with each
/// scaled record through the support alone; none without a support.
pub fn floor_curves(set: &RecordSet, d: &DynamicCheck) -> Vec<Curve> {
    let mut curves = Vec::new();
    if let Some(floor) = &d.floor_g {
        curves.push(Curve {
            label: Some(format!("{} code floor spectrum S_eZ, 5%", d.limit_state)),
            ink: Ink::Series { index: 0, of: 2 },
            width: 3,
            dashed: true,
            points: set.periods.iter().copied().zip(floor.iter().copied()).collect(),
        });
    }
    if let Some(mean) = &d.floor_mean_g {
        curves.push(Curve {
            label: Some("mean floor spectrum computed on the support's top".into()),
            ink: Ink::Series { index: 1, of: 2 },
            width: 3,
            dashed: false,
            points: set.periods.iter().copied().zip(mean.iter().copied()).collect(),
        });
    }
    curves
}
