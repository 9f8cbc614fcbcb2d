//! The transition conditions of docs/src/model.md, "Regimes and transitions", each a function that is
//! negative while the regime holds and crosses zero upwards when it must
//! change, evaluated on `f64` or, with its exact time derivative, on [`Jet`].

use crate::equations::Kernel;
use crate::jet::Real;
use crate::regime::{BuildingRegime, Regime, State, TowerRegime};
use std::f64::consts::FRAC_PI_2;

/// A condition for leaving the current regime.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Condition {
    /// The pivot line accelerates beyond `g_e tan α` towards `+x`: rock on the `−x` corner.
    UpliftNegative,
    /// … towards `−x`: rock on the `+x` corner.
    UpliftPositive,
    /// `θ` returns to zero.
    Impact,
    /// `|θ|` reaches `π/2`.
    Overturn,
    /// The stick demand exceeds `μs N` towards `+x`: slip towards `−x`.
    SlipNegative,
    /// … towards `−x`: slip towards `+x`.
    SlipPositive,
    /// The slip velocity returns to zero.
    SlipStop,
}

pub(crate) const MAX_CONDITIONS: usize = 4;

/// The conditions that can end `regime`, at most four, in the order in which
/// they are applied when several hold at one instant (a jump of the input):
/// the tower's first, unless [`slips_before_uplift`].
#[inline(always)]
pub(crate) fn conditions(kernel: &Kernel, regime: Regime) -> ([Condition; MAX_CONDITIONS], usize) {
    let tower: &[Condition] = match (kernel.has_tower, regime.tower) {
        (false, _) => &[],
        (true, TowerRegime::Rest) => &[Condition::UpliftNegative, Condition::UpliftPositive],
        (true, TowerRegime::Rocking(_)) => &[Condition::Overturn, Condition::Impact],
    };
    let building: &[Condition] = match (kernel.has_building, regime.building) {
        (false, _) => &[],
        (true, BuildingRegime::Stick) => &[Condition::SlipNegative, Condition::SlipPositive],
        (true, BuildingRegime::Slip(_)) => &[Condition::SlipStop],
    };
    let order = if slips_before_uplift(kernel, regime) {
        [building, tower]
    } else {
        [tower, building]
    };
    let mut list = [Condition::Impact; MAX_CONDITIONS];
    let mut n = 0;
    for &c in order.iter().flat_map(|part| part.iter()) {
        list[n] = c;
        n += 1;
    }
    (list, n)
}

/// Whether a building that is stuck under a standing tower slips before the
/// tower can lift, when a jump of the input makes both conditions hold at
/// once: with the tower standing, both compare the pivot line's acceleration
/// `|a_g|` with a threshold, `μs g_e` for the slip and `g_e tan α` for the
/// uplift, and a jump passes the lower one first. So where `μs < tan α` the
/// building slips first, and sliding it carries the tower at `μk g_e < g_e
/// tan α`: the tower stays standing (a 1.5 g rectangular pulse under a
/// building with μs = 0.2 lifted the tower first and reported an uplift and an
/// impact at t = 0 while θ stayed 0).
pub(crate) fn slips_before_uplift(kernel: &Kernel, regime: Regime) -> bool {
    kernel.has_tower && kernel.has_building && regime.tower == TowerRegime::Rest && regime.building == BuildingRegime::Stick && kernel.mu_s < kernel.tan_alpha
}

/// `s = ±1` of a rocking tower (0 at rest).
pub(crate) fn pivot_sign(regime: Regime) -> f64 {
    match regime.tower {
        TowerRegime::Rocking(p) => p.sign(),
        TowerRegime::Rest => 0.0,
    }
}

impl Condition {
    /// The value of the condition in `regime`: negative while the regime holds.
    #[inline]
    pub(crate) fn value<T: Real>(self, kernel: &Kernel, regime: Regime, a_g: T, g_e: T, y: &State<T>) -> T {
        let s = pivot_sign(regime);
        match self {
            Condition::UpliftNegative | Condition::UpliftPositive => {
                let acc_pivot = kernel.pivot_acceleration_at_rest(regime.building, a_g, g_e);
                let toward = if self == Condition::UpliftNegative { acc_pivot } else { -acc_pivot };
                toward - kernel.uplift_threshold(g_e)
            }
            Condition::Impact | Condition::Overturn => self.theta_margin(s, y.theta),
            Condition::SlipNegative | Condition::SlipPositive => {
                let (force, normal) = kernel.stick_demand(regime.tower, a_g, g_e, y.theta, y.theta_dot);
                self.slip_margin(kernel, force, normal)
            }
            Condition::SlipStop => match regime.building {
                BuildingRegime::Slip(dir) => -(y.slip_vel * dir.sign()),
                BuildingRegime::Stick => T::from(-1.0),
            },
        }
    }

    /// A condition of `θ` alone ([`Condition::of_theta`]) on pivot `s`: the
    /// impact margin or the overturn margin.
    #[inline(always)]
    pub(crate) fn theta_margin<T: Real>(self, s: f64, theta: T) -> T {
        debug_assert!(self.of_theta(), "{self:?} is not a condition of θ alone");
        if self == Condition::Impact {
            Self::impact_margin(s, theta)
        } else {
            Self::overturn_margin(s, theta)
        }
    }

    /// [`Condition::Impact`] on pivot `s`: `−s θ`.
    #[inline(always)]
    fn impact_margin<T: Real>(s: f64, theta: T) -> T {
        -(theta * s)
    }

    /// [`Condition::Overturn`] on pivot `s`: `s θ − π/2`.
    #[inline(always)]
    fn overturn_margin<T: Real>(s: f64, theta: T) -> T {
        theta * s - FRAC_PI_2
    }

    /// The slip conditions from the stick demand: `±F_req − μs N`, the
    /// static friction law ([`Kernel::static_friction_margin`]) towards the
    /// side the slip starts from.
    #[inline(always)]
    pub(crate) fn slip_margin<T: Real>(self, kernel: &Kernel, force: T, normal: T) -> T {
        let toward = if self == Condition::SlipNegative { force } else { -force };
        kernel.static_friction_margin(toward, normal)
    }

    /// Whether the condition starts its regime on zero and moves away from
    /// it: the impact (`θ = 0` after an uplift or an impact) and the end of
    /// a slip (`u̇ = 0` when it starts). Such a condition is armed once the
    /// motion has left zero.
    pub(crate) fn departs_from_zero(self) -> bool {
        matches!(self, Condition::Impact | Condition::SlipStop)
    }

    /// Whether the condition lifts a standing tower.
    pub(crate) fn lifts(self) -> bool {
        matches!(self, Condition::UpliftNegative | Condition::UpliftPositive)
    }

    /// Whether the condition is a function of `θ` alone (its extrema are those of `θ`).
    pub(crate) fn of_theta(self) -> bool {
        matches!(self, Condition::Impact | Condition::Overturn)
    }

    /// Whether the condition depends on the ground acceleration (else it is
    /// evaluated without computing `a_g`, which saves a sine in root finding).
    pub(crate) fn uses_ground(self) -> bool {
        !matches!(self, Condition::Impact | Condition::Overturn | Condition::SlipStop)
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            Condition::UpliftNegative | Condition::UpliftPositive => "uplift",
            Condition::Impact => "impact",
            Condition::Overturn => "overturn",
            Condition::SlipNegative | Condition::SlipPositive => "slip",
            Condition::SlipStop => "slip stop",
        }
    }
}
