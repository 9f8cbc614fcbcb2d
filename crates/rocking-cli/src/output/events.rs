//! `events.csv`: `t,kind,theta,theta_dot_before,theta_dot_after,slip_vel`, and
//! the additions `slip,regime` (the combined motion after the event).

use super::number;
use anyhow::Context;
use rocking::Event;
use std::path::Path;

/// The columns.
pub const COLUMNS: [&str; 8] = ["t", "kind", "theta", "theta_dot_before", "theta_dot_after", "slip_vel", "slip", "regime"];

/// Writes the events; `theta`, `slip_vel` and `slip` are those after the event.
pub fn write_events(path: &Path, events: &[Event]) -> anyhow::Result<()> {
    let context = || format!("cannot write {}", path.display());
    let mut w = csv::Writer::from_path(path).with_context(context)?;
    w.write_record(COLUMNS).with_context(context)?;
    let mut buffer = ryu::Buffer::new();
    let empty: [&[u8]; 0] = [];
    for e in events {
        w.write_field(number(&mut buffer, e.time)).with_context(context)?;
        w.write_field(e.kind.as_str()).with_context(context)?;
        for x in [e.after.theta, e.before.theta_dot, e.after.theta_dot, e.after.slip_vel, e.after.slip] {
            w.write_field(number(&mut buffer, x)).with_context(context)?;
        }
        w.write_field(e.regime.motion().as_str()).with_context(context)?;
        w.write_record(empty).with_context(context)?;
    }
    w.flush().with_context(context)
}
