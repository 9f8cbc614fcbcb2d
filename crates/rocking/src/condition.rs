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
/// the tower's first, unless the building slips first
/// ([`Kernel::slips_before_uplift`]).
#[inline(always)]
pub(crate) fn conditions(kernel: &Kernel, regime: Regime) -> &'static [Condition] {
    use Condition::{Impact, Overturn, SlipNegative, SlipPositive, SlipStop, UpliftNegative, UpliftPositive};
    let tower = kernel.has_tower.then_some(regime.tower);
    let building = kernel.has_building.then_some(regime.building);
    match (tower, building) {
        (None, None) => &[],
        (None, Some(BuildingRegime::Stick)) => &[SlipNegative, SlipPositive],
        (None, Some(BuildingRegime::Slip(_))) => &[SlipStop],
        (Some(TowerRegime::Rest), None) => &[UpliftNegative, UpliftPositive],
        (Some(TowerRegime::Rest), Some(BuildingRegime::Stick)) if kernel.slips_before_uplift() => &[SlipNegative, SlipPositive, UpliftNegative, UpliftPositive],
        (Some(TowerRegime::Rest), Some(BuildingRegime::Stick)) => &[UpliftNegative, UpliftPositive, SlipNegative, SlipPositive],
        (Some(TowerRegime::Rest), Some(BuildingRegime::Slip(_))) => &[UpliftNegative, UpliftPositive, SlipStop],
        (Some(TowerRegime::Rocking(_)), None) => &[Overturn, Impact],
        (Some(TowerRegime::Rocking(_)), Some(BuildingRegime::Stick)) => &[Overturn, Impact, SlipNegative, SlipPositive],
        (Some(TowerRegime::Rocking(_)), Some(BuildingRegime::Slip(_))) => &[Overturn, Impact, SlipStop],
    }
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
    /// static friction law ([`Friction::static_friction_margin`](crate::body::Friction::static_friction_margin)) towards the
    /// side the slip starts from.
    #[inline(always)]
    pub(crate) fn slip_margin<T: Real>(self, kernel: &Kernel, force: T, normal: T) -> T {
        let toward = if self == Condition::SlipNegative { force } else { -force };
        kernel.friction.static_friction_margin(toward, normal)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::solid_block;
    use crate::regime::{Pivot, SlipDirection};
    use crate::{Building, Model, NormalForce};
    use Condition::{Impact, Overturn, SlipNegative, SlipPositive, SlipStop, UpliftNegative, UpliftPositive};

    /// The table of [`conditions`] against the rule it is written from: the
    /// tower's conditions (an uplift either way at rest; the overturning and
    /// the impact while rocking) then the building's (a slip either way while
    /// stuck; the end of the slip while sliding), the building's first where
    /// it slips before the tower lifts ([`Kernel::slips_before_uplift`],
    /// tested against the slip and uplift laws beside them); none of a body
    /// the model lacks; never more than `MAX_CONDITIONS`, the room `watched`
    /// has for them. Every
    /// regime of the 0.5 m × 2 m block (tan α = 0.25), alone, on a building
    /// with μs = 0.6 and 0.2 (above and below tan α), and the building alone.
    #[test]
    fn each_regime_is_ended_by_its_bodies_conditions_in_the_order_of_the_rule() {
        let building = |mu_s: f64| Building::new(2.0e6, mu_s, 0.75 * mu_s, NormalForce::Dynamic).unwrap_or_else(|e| panic!("{e}"));
        let models = [
            Model::new(Some(solid_block(0.5, 2.0)), None, 9.81),
            Model::new(Some(solid_block(0.5, 2.0)), Some(building(0.6)), 9.81),
            Model::new(Some(solid_block(0.5, 2.0)), Some(building(0.2)), 9.81),
            Model::new(None, Some(building(0.6)), 9.81),
        ];
        let towers = [TowerRegime::Rest, TowerRegime::Rocking(Pivot::Negative), TowerRegime::Rocking(Pivot::Positive)];
        let buildings = [
            BuildingRegime::Stick,
            BuildingRegime::Slip(SlipDirection::Negative),
            BuildingRegime::Slip(SlipDirection::Positive),
        ];
        let mut seen = 0;
        for model in models {
            let kernel = Kernel::new(&model.unwrap_or_else(|e| panic!("{e}")));
            for (tower, building) in towers.iter().flat_map(|&t| buildings.iter().map(move |&b| (t, b))) {
                let regime = Regime { tower, building };
                let tower_part: Vec<Condition> = match (kernel.has_tower, tower) {
                    (false, _) => vec![],
                    (true, TowerRegime::Rest) => vec![UpliftNegative, UpliftPositive],
                    (true, TowerRegime::Rocking(_)) => vec![Overturn, Impact],
                };
                let building_part: Vec<Condition> = match (kernel.has_building, building) {
                    (false, _) => vec![],
                    (true, BuildingRegime::Stick) => vec![SlipNegative, SlipPositive],
                    (true, BuildingRegime::Slip(_)) => vec![SlipStop],
                };
                // The building first only under a standing tower on a stuck
                // building that slips before the tower lifts (μs < tan α).
                let building_first = tower == TowerRegime::Rest && building == BuildingRegime::Stick && kernel.slips_before_uplift();
                let expected: Vec<Condition> = if building_first {
                    [building_part, tower_part].concat()
                } else {
                    [tower_part, building_part].concat()
                };
                let list = conditions(&kernel, regime);
                assert_eq!(
                    list,
                    expected.as_slice(),
                    "{regime:?}, tower {}, building {}",
                    kernel.has_tower,
                    kernel.has_building
                );
                assert!(list.len() <= MAX_CONDITIONS);
                seen += usize::from(building_first);
            }
        }
        // The reversed order is met (μs = 0.2 under the standing tower), or it is not tested.
        assert_eq!(seen, 1);
    }
}
