//! The peaks inside a step, up to its first transition, fed to the summary:
//! θ at the extremes found by the search for transitions, and the top
//! acceleration, `f_y` and the pivot's friction demand at the extrema the
//! screen could not rule out, located on their exact time derivatives
//! (`extrema.rs`).

use super::crossing::Points;
use super::screen::{Ends, Screen};
use super::watch::watched_on;
use crate::extrema::interior_extrema;
use crate::integrator::DenseOutput;
use crate::response::Tracker;

/// Feeds `tracker` the peaks of the step `e` up to `t_stop`.
#[inline(always)]
pub(super) fn inside<const N: usize>(e: &Ends, screen: &Screen, dense: Option<&DenseOutput<N>>, theta_points: &Points, t_stop: f64, tracker: &mut Tracker) {
    for &(t, theta) in theta_points.as_slice() {
        if t <= t_stop {
            tracker.theta(theta);
        }
    }
    let Some(d) = dense else { return };
    let (t0, t1, w0, w1) = (e.t0, e.t1, e.w0, e.w1);
    // The peaks alone: no condition is evaluated (an empty list).
    let at = |t: f64| watched_on(e.kernel, e.regime, e.pieces, &[], d, t);
    if screen.top {
        interior_extrema(t0, w0.top, t1, w1.top, &mut |t| at(t).top, screen.top_matters(), &mut |t, v| {
            if t <= t_stop {
                tracker.top(v);
            }
        });
    }
    if screen.fy {
        interior_extrema(t0, w0.fy, t1, w1.fy, &mut |t| at(t).fy, screen.fy_matters(), &mut |t, v| {
            if t <= t_stop && v <= 0.0 {
                tracker.reaction_lost();
            }
        });
    }
    if screen.ratio {
        let ratio = Ends::ratio;
        interior_extrema(t0, ratio(w0), t1, ratio(w1), &mut |t| ratio(&at(t)), screen.demand_matters(), &mut |t, _| {
            if t <= t_stop {
                let w = at(t);
                tracker.pivot(w.fx.v, w.fy.v);
            }
        });
    }
}
