//! The hazard curve of surface PGA and the mean annual frequency of a limit
//! state against numbers worked out independently: Cornell's closed form on
//! one power law, the limit β → 0, and a site of a 2 × 2 grid whose curve and
//! integral were computed by hand (Python, mpmath at 30 digits: the haversine,
//! Allegato A's inverse-distance weights, NTC's SS on soil C with ST 1.2, then
//! the integral `∫ Φ(ln(a/θ)/β) |dλ/da| da` by quadrature on each segment).

use approx::assert_relative_eq;
use rocking_codes::{power_law_frequency, probability_in_period, HazardCurve, HazardGrid, HazardPoint, Soil, Topography, GRID_RETURN_PERIODS};

/// Nine points on `λ = k0 a^(−k)` at the grid's return periods.
fn power_law_curve(k0: f64, k: f64) -> HazardCurve {
    let points = GRID_RETURN_PERIODS
        .iter()
        .map(|&tr| {
            let lambda = 1.0 / tr;
            let pga = (k0 / lambda).powf(1.0 / k);
            HazardPoint {
                return_period: tr,
                ag: pga,
                s: 1.0,
                pga,
                annual_frequency: lambda,
            }
        })
        .collect();
    HazardCurve::from_points(points).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn one_power_law_gives_cornells_closed_form() {
    // k0 θ^(−k) exp(k² β² / 2); the sum of closed-form segments equals it to
    // round-off (the segments' k differ from 2.7 by the points' rounding):
    // 1e-6 is the contract's tolerance, met with room.
    let (k0, k) = (1.2e-4, 2.7);
    let curve = power_law_curve(k0, k);
    for (theta, beta) in [(0.05, 0.3), (0.3, 0.5), (1.5, 0.8), (0.2, 0.05)] {
        let expected = k0 * f64::powf(theta, -k) * (0.5 * k * k * beta * beta).exp();
        assert_relative_eq!(power_law_frequency(k0, k, theta, beta), expected, max_relative = 1e-14);
        assert_relative_eq!(curve.limit_state_frequency(theta, beta).annual_frequency, expected, max_relative = 1e-6);
    }
}

#[test]
fn a_vanishing_dispersion_gives_the_hazard_at_the_median() {
    // β = 1e-6: λ_LS = λ(θ) exp(k² β² / 2) inside a segment, 1 + 4e-12 for k ≈ 3;
    // λ(θ) computed by hand on the segment of the site below (its 101–140 years points).
    let curve = site_curve();
    let p = curve.points();
    let (a1, l1, a2, l2) = (p[3].pga, p[3].annual_frequency, p[4].pga, p[4].annual_frequency);
    let theta = 0.32;
    let k = (l1 / l2).ln() / (a2 / a1).ln();
    let by_hand = l1 * (theta / a1).powf(-k);
    assert_relative_eq!(curve.annual_frequency(theta), by_hand, max_relative = 1e-12);
    assert_relative_eq!(curve.limit_state_frequency(theta, 1e-6).annual_frequency, by_hand, max_relative = 1e-9);
}

/// The 2 × 2 grid (0.1° apart from 10 E, 45 N): node `n`'s ag (g/10) and F0 at return period `k`.
fn node_values(n: usize, k: usize) -> (f64, f64, f64) {
    let (n, k) = (n as f64, k as f64);
    ((0.4 + 0.2 * n) * (1.0 + 0.45 * k), 2.4 + 0.03 * n + 0.02 * k, 0.26 + 0.01 * n + 0.01 * k)
}

fn site_curve() -> HazardCurve {
    let mut text = String::from("LON LAT");
    for tr in GRID_RETURN_PERIODS {
        text += &format!(" ag{tr} F0{tr} Tc{tr}");
    }
    for (n, (lon, lat)) in [(10.0, 45.0), (10.1, 45.0), (10.0, 45.1), (10.1, 45.1)].iter().enumerate() {
        text += &format!("\n{lon} {lat}");
        for k in 0..9 {
            let (ag, f0, tc) = node_values(n, k);
            text += &format!(" {ag} {f0} {tc}");
        }
    }
    let grid = HazardGrid::parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let hazard = grid.site(10.03, 45.07).unwrap_or_else(|e| panic!("{e}"));
    HazardCurve::of_site(&hazard, Soil::C, Topography::T2).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_curves_points_are_allegato_as_ag_times_s() {
    // (TR, ag, S, ag·S) by hand; S clamped at 1.5 · 1.2 at the first two.
    let by_hand = [
        (30.0, 0.07378365473754306, 1.7999999999999998, 0.1328105785275775),
        (50.0, 0.10698629936943743, 1.7999999999999998, 0.19257533886498737),
        (72.0, 0.1401889440013318, 1.7886010807057253, 0.25074209674377645),
        (101.0, 0.1733915886332262, 1.7265623925228684, 0.29937139611392405),
        (140.0, 0.20659423326512052, 1.6635674681746127, 0.3436834455723319),
        (201.0, 0.23979687789701493, 1.5996163076609584, 0.38358299641024873),
        (475.0, 0.27299952252890936, 1.5347089109819056, 0.41897479991892267),
        (975.0, 0.3062021671608037, 1.4688452781374541, 0.4497636073896019),
        (2475.0, 0.33940481179269805, 1.402025409127604, 0.4758541701135349),
    ];
    let curve = site_curve();
    assert_eq!(curve.points().len(), 9);
    for (p, (tr, ag, s, pga)) in curve.points().iter().zip(by_hand) {
        // A haversine, four quotients and a product: 1e-12 is a thousand times their round-off.
        assert_relative_eq!(p.return_period, tr, max_relative = 1e-15);
        assert_relative_eq!(p.ag, ag, max_relative = 1e-12);
        assert_relative_eq!(p.s, s, max_relative = 1e-12);
        assert_relative_eq!(p.pga, pga, max_relative = 1e-12);
        assert_relative_eq!(p.annual_frequency, 1.0 / tr, max_relative = 1e-15);
    }
}

#[test]
fn the_integral_over_the_sites_curve_agrees_with_a_quadrature() {
    // θ = 0.35 g, β = 0.4: mpmath's quadrature of the original integrand
    // (30 digits) over the ten pieces, 0 and ∞ included. The closed form is
    // exact; 1e-9 covers the round-off of the nine segments' laws.
    let r = site_curve().limit_state_frequency(0.35, 0.4);
    assert_relative_eq!(r.annual_frequency, 0.007872419631203495, max_relative = 1e-9);
    // The shares of the ground motions below 30 years' PGA and above 2475 years':
    // a difference of two terms for the first, so 1e-7.
    assert_relative_eq!(r.share_below, 0.007092635763673528, max_relative = 1e-7);
    assert_relative_eq!(r.share_above, 0.04199865901320505, max_relative = 1e-9);
    // P = 1 − exp(−λ VR), by hand for VR = 50.
    assert_relative_eq!(
        probability_in_period(r.annual_frequency, 50.0),
        1.0 - (-0.007872419631203495f64 * 50.0).exp(),
        max_relative = 1e-9
    );
}

#[test]
fn a_surface_pga_that_falls_with_the_return_period_is_refused() {
    // Soil D: S = 2.4 − 1.5 F0 ag falls faster than ag grows once F0 ag > 0.8.
    let mut points: Vec<HazardPoint> = site_curve().points().to_vec();
    points[5].pga = points[4].pga * 0.99;
    let e = HazardCurve::from_points(points).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("does not grow"), "{e}");
}

/// The risk figure's density per unit of ln a integrates over ln a to the
/// closed-form λ_LS of the site's curve (a second method: Simpson's rule on
/// 20,000 steps of ln a in each of the ten pieces the curve's points cut,
/// since the density jumps there with the slope k; the end pieces reach
/// θ e^(±12β) and the points ×/÷ 1e3, beyond which the integrand is below
/// 1e-12 of λ_LS; the rule's error, h⁴ f⁗/180 per piece with h ≤ 4e-4 and
/// the steepest slope k = 16.5, is below 1e-11 of it).
#[test]
fn the_density_integrates_to_the_limit_state_frequency() {
    let curve = site_curve();
    for (theta, beta) in [(0.3, 0.4), (0.05, 0.2), (1.2, 0.6)] {
        let exact = curve.limit_state_frequency(theta, beta).annual_frequency;
        let first = curve.points()[0].pga;
        let last = curve.points()[curve.points().len() - 1].pga;
        let mut edges = vec![(theta * (-12.0 * beta).exp()).min(first / 1e3).ln()];
        edges.extend(curve.points().iter().map(|p| p.pga.ln()));
        edges.push((theta * (12.0 * beta).exp()).max(last * 1e3).ln());
        let n = 20_000;
        let simpson: f64 = edges
            .windows(2)
            .map(|w| {
                let h = (w[1] - w[0]) / n as f64;
                // Just inside the piece at its ends, so that each end takes this piece's slope.
                let at = |i: usize| (w[0] + i as f64 * h).clamp(w[0] + 1e-12, w[1] - 1e-12).exp();
                let f = |i: usize| curve.limit_state_density(theta, beta, at(i));
                let inner: f64 = (1..n).map(|i| if i % 2 == 1 { 4.0 } else { 2.0 } * f(i)).sum();
                h / 3.0 * (f(0) + inner + f(n))
            })
            .sum();
        assert_relative_eq!(simpson, exact, max_relative = 1e-9);
    }
}
