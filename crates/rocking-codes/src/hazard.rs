//! Risk at a site: the hazard curve of surface PGA from the grid's nine
//! return periods, and the mean annual frequency of exceeding a limit state
//! whose fragility is lognormal (the total probability theorem; Cornell et
//! al. 2002).
//!
//! The hazard curve: at each of [`GRID_RETURN_PERIODS`], `λ = 1/TR` at
//! `a = ag(TR) · S(ag(TR))` (S the site's soil and topography factors at that
//! ag, NTC 2018 §3.2.3.2); between two points `ln λ` linear in `ln a` (a power
//! law `λ = k0 a^(−k)`), below the first point the first segment's law, above
//! the last the last segment's.
//!
//! The integral `λ_LS = ∫ Φ(ln(a/θ)/β) |dλ/da| da`, by parts, is
//! `∫ λ(a) f(a) da` with `f` the lognormal density of the capacity (median θ,
//! dispersion β): the boundary terms vanish at 0 and ∞. On a power-law
//! segment `[a1, a2]` that integral has a closed form
//! ([`power_law_segment_frequency`]), so the whole curve's is a sum of
//! positive terms, exact to rounding: no quadrature.

use crate::elastic::Soil;
use crate::error::{invalid, Error};
use crate::grid::{SiteHazard, GRID_RETURN_PERIODS};
use crate::ntc::{ntc_ss, Topography};

/// One point of the hazard curve: the grid's return period, the site's ag and
/// S there, the surface PGA `ag · S` and its annual frequency `1/TR`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HazardPoint {
    /// The return period (years).
    pub return_period: f64,
    /// `ag` on rock (g), Allegato A's interpolation at the site.
    pub ag: f64,
    /// `S = SS · ST` at that ag.
    pub s: f64,
    /// The surface PGA `ag · S` (g).
    pub pga: f64,
    /// The mean annual frequency of exceedance `1/TR` (1/year).
    pub annual_frequency: f64,
}

/// The hazard curve of a site: piecewise power law through its points.
#[derive(Debug, Clone, PartialEq)]
pub struct HazardCurve {
    points: Vec<HazardPoint>,
}

/// The mean annual frequency of a limit state and where it comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitStateFrequency {
    /// `λ_LS` (1/year).
    pub annual_frequency: f64,
    /// The part of `λ_LS` from PGAs below the curve's first point (return periods under 30 years), a fraction of it.
    pub share_below: f64,
    /// The part from PGAs above the last point (return periods over 2475 years), a fraction of it.
    pub share_above: f64,
}

/// The surface PGA `ag · S` (g) of NTC 2018 §3.2.3.2.1 at one return period:
/// `S = SS(soil, ag, F0) · ST`.
pub fn surface_pga(ag: f64, f0: f64, soil: Soil, topography: Topography) -> (f64, f64) {
    let s = ntc_ss(soil, ag, f0) * topography.st();
    (ag * s, s)
}

/// The power law `λ = k0 a^(−k)` through two points `(a1, λ1)`, `(a2, λ2)`
/// (`a1 < a2`, `λ1 > λ2`): `k = ln(λ1/λ2) / ln(a2/a1)`, `k0 = λ1 a1^k`.
pub fn power_law_through(a1: f64, lambda1: f64, a2: f64, lambda2: f64) -> (f64, f64) {
    let k = libm::log(lambda1 / lambda2) / libm::log(a2 / a1);
    (lambda1 * libm::pow(a1, k), k)
}

/// The standard normal distribution function `Φ(x)`.
pub fn standard_normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x / std::f64::consts::SQRT_2)
}

/// `Φ(u2) − Φ(u1)` for `u1 ≤ u2`, from the upper tail when both are positive
/// (so that two values near 1 do not cancel).
fn normal_mass_between(u1: f64, u2: f64) -> f64 {
    if u1 > 0.0 {
        standard_normal_cdf(-u1) - standard_normal_cdf(-u2)
    } else {
        standard_normal_cdf(u2) - standard_normal_cdf(u1)
    }
}

/// `∫_{a1}^{a2} λ(a) f(a) da` for the power law `λ = k0 a^(−k)` and the
/// lognormal density `f` of median `θ` and dispersion `β` (`0 ≤ a1 < a2 ≤ ∞`):
/// completing the square in `ln a`,
/// `k0 θ^(−k) exp(k² β² / 2) [Φ(u2) − Φ(u1)]`, `u = ln(a/θ)/β + k β`.
pub fn power_law_segment_frequency(k0: f64, k: f64, theta: f64, beta: f64, a1: f64, a2: f64) -> f64 {
    let u = |a: f64| libm::log(a / theta) / beta + k * beta;
    let mass = normal_mass_between(u(a1), u(a2));
    if mass <= 0.0 {
        return 0.0;
    }
    libm::exp(libm::log(k0) - k * libm::log(theta) + 0.5 * k * k * beta * beta + libm::log(mass))
}

/// The closed form on one power law over all PGAs, `λ_LS = k0 θ^(−k) exp(k² β² / 2)`
/// (Cornell et al. 2002): [`power_law_segment_frequency`] from 0 to ∞.
pub fn power_law_frequency(k0: f64, k: f64, theta: f64, beta: f64) -> f64 {
    k0 * libm::pow(theta, -k) * libm::exp(0.5 * k * k * beta * beta)
}

/// The probability of at least one exceedance in `years`, a Poisson process
/// of rate `λ`: `P = 1 − exp(−λ VR)`.
pub fn probability_in_period(annual_frequency: f64, years: f64) -> f64 {
    -libm::expm1(-annual_frequency * years)
}

impl HazardCurve {
    /// The curve of a site from its parameters at the grid's nine return
    /// periods, its soil and topography. An error when the surface PGA does
    /// not grow with the return period (S falling faster than ag grows, as on
    /// soil D at high ag): no power law joins such points.
    pub fn of_site(hazard: &SiteHazard, soil: Soil, topography: Topography) -> Result<Self, Error> {
        let points: Vec<HazardPoint> = GRID_RETURN_PERIODS
            .iter()
            .zip(hazard.sites)
            .map(|(&tr, site)| {
                let (pga, s) = surface_pga(site.ag, site.f0, soil, topography);
                HazardPoint {
                    return_period: tr,
                    ag: site.ag,
                    s,
                    pga,
                    annual_frequency: 1.0 / tr,
                }
            })
            .collect();
        Self::from_points(points)
    }

    /// A curve through the given points, in order of growing PGA and falling frequency (at least two).
    pub fn from_points(points: Vec<HazardPoint>) -> Result<Self, Error> {
        if points.len() < 2 {
            return Err(invalid("site", "a hazard curve needs at least two points"));
        }
        if let Some(w) = points
            .windows(2)
            .find(|w| !(w[1].pga > w[0].pga && w[1].annual_frequency < w[0].annual_frequency))
        {
            return Err(invalid(
                "site",
                format!(
                    "the surface PGA ag·S does not grow from {} g at {} years to {} g at {} years (S falls faster than ag grows): no hazard curve of surface PGA joins them",
                    w[0].pga, w[0].return_period, w[1].pga, w[1].return_period
                ),
            ));
        }
        if let Some(p) = points.iter().find(|p| !(p.pga > 0.0 && p.pga.is_finite() && p.annual_frequency > 0.0)) {
            return Err(invalid(
                "site",
                format!("a hazard point must have PGA and frequency > 0, got {} g at {} years", p.pga, p.return_period),
            ));
        }
        Ok(Self { points })
    }

    /// The points, in order of growing PGA.
    pub fn points(&self) -> &[HazardPoint] {
        &self.points
    }

    /// The power laws `(k0, k)` of the segments, in order; the first also holds below the first point, the last above the last.
    pub fn segments(&self) -> Vec<(f64, f64)> {
        self.points
            .windows(2)
            .map(|w| power_law_through(w[0].pga, w[0].annual_frequency, w[1].pga, w[1].annual_frequency))
            .collect()
    }

    /// `λ(a)` (1/year) at the surface PGA `a` (g, > 0).
    pub fn annual_frequency(&self, pga: f64) -> f64 {
        let (k0, slope) = self.segment_at(pga);
        k0 * libm::pow(pga, -slope)
    }

    /// The power law `(k0, k)` of the segment that holds at `pga` (g, > 0).
    fn segment_at(&self, pga: f64) -> (f64, f64) {
        let k = self.points[1..self.points.len() - 1].partition_point(|p| p.pga <= pga);
        self.segments()[k]
    }

    /// The integrand of [`HazardCurve::limit_state_frequency`] per unit of
    /// `ln a` at the surface PGA `a` (g, > 0): `Φ(ln(a/θ)/β) |dλ/d ln a|`,
    /// `|dλ/d ln a| = k λ(a)` on the segment's power law. Its integral over
    /// `ln a` is `λ_LS`; divided by `λ_LS` it shows where that frequency comes
    /// from (the risk figure).
    pub fn limit_state_density(&self, theta: f64, beta: f64, pga: f64) -> f64 {
        let (k0, slope) = self.segment_at(pga);
        standard_normal_cdf(libm::log(pga / theta) / beta) * slope * k0 * libm::pow(pga, -slope)
    }

    /// The mean annual frequency of exceeding a limit state whose fragility is
    /// lognormal (median `θ` in g, dispersion `β` > 0): the sum over the
    /// segments of [`power_law_segment_frequency`], the end segments extended
    /// to 0 and ∞; with the shares of the two extensions.
    ///
    /// A share is that of the ground motions in the extension, the integral
    /// `∫ Φ(ln(a/θ)/β) |dλ/da| da` over it: the by-parts form's part plus its
    /// boundary term `λ(a) Φ(ln(a/θ)/β)` at the curve's end point.
    pub fn limit_state_frequency(&self, theta: f64, beta: f64) -> LimitStateFrequency {
        let segments = self.segments();
        let (first, last) = (self.points[0].pga, self.points[self.points.len() - 1].pga);
        let (k0, k) = segments[0];
        let below = power_law_segment_frequency(k0, k, theta, beta, 0.0, first);
        let (k0, k) = segments[segments.len() - 1];
        let above = power_law_segment_frequency(k0, k, theta, beta, last, f64::INFINITY);
        let inside: f64 = segments
            .iter()
            .zip(self.points.windows(2))
            .map(|(&(k0, k), w)| power_law_segment_frequency(k0, k, theta, beta, w[0].pga, w[1].pga))
            .sum();
        let total = below + inside + above;
        let boundary = |p: &HazardPoint| p.annual_frequency * standard_normal_cdf(libm::log(p.pga / theta) / beta);
        LimitStateFrequency {
            annual_frequency: total,
            share_below: ((below - boundary(&self.points[0])) / total).max(0.0),
            share_above: (above + boundary(&self.points[self.points.len() - 1])) / total,
        }
    }
}
