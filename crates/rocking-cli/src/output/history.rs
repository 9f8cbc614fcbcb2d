//! `history.csv`: `t,ground_acc,theta,theta_dot,slip,slip_vel,top_dx,top_abs_acc,regime`,
//! then `pK_dx,pK_abs_acc` for each extra point K = 1, 2, … of `tower.points`.

use super::number;
use anyhow::Context;
use rocking::History;
use std::path::Path;

/// The columns before the extra points.
pub const COLUMNS: [&str; 9] = ["t", "ground_acc", "theta", "theta_dot", "slip", "slip_vel", "top_dx", "top_abs_acc", "regime"];

/// Writes the history (SI units: s, m/s², rad, rad/s, m, m/s).
pub fn write_history(path: &Path, history: &History, points: usize) -> anyhow::Result<()> {
    let context = || format!("cannot write {}", path.display());
    let mut w = csv::Writer::from_path(path).with_context(context)?;
    let mut header: Vec<String> = COLUMNS.iter().map(|c| c.to_string()).collect();
    for k in 1..=points {
        header.push(format!("p{k}_dx"));
        header.push(format!("p{k}_abs_acc"));
    }
    w.write_record(&header).with_context(context)?;
    let mut buffer = ryu::Buffer::new();
    let empty: [&[u8]; 0] = [];
    for (sample, extra) in history.samples.iter().zip(&history.point_values) {
        let s = sample.state;
        for x in [
            sample.t,
            sample.ground_acc,
            s.theta,
            s.theta_dot,
            s.slip,
            s.slip_vel,
            sample.top_dx,
            sample.top_abs_acc,
        ] {
            w.write_field(number(&mut buffer, x)).with_context(context)?;
        }
        w.write_field(sample.motion.as_str()).with_context(context)?;
        for &(dx, acc) in extra {
            w.write_field(number(&mut buffer, dx)).with_context(context)?;
            w.write_field(number(&mut buffer, acc)).with_context(context)?;
        }
        w.write_record(empty).with_context(context)?;
    }
    w.flush().with_context(context)
}
