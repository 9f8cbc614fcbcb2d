//! `events.csv`: the columns of [`rocking_scenario::columns::EVENTS`].

use super::write_value;
use anyhow::Context;
use rocking::Event;
use rocking_scenario::columns::{event_kind, Layout, EVENTS, KIND};
use std::path::Path;

/// Writes the events to `path`; `shown` names the file in errors.
pub fn write_events(path: &Path, shown: &Path, layout: &Layout, events: &[Event]) -> anyhow::Result<()> {
    let context = || format!("cannot write {}", shown.display());
    let columns: Vec<_> = EVENTS.iter().filter(|c| (c.present)(layout)).collect();
    let mut w = csv::Writer::from_path(path).with_context(context)?;
    w.write_record(columns.iter().map(|c| c.name)).with_context(context)?;
    let mut buffer = ryu::Buffer::new();
    for e in events {
        for c in &columns {
            if c.name == KIND {
                w.write_field(event_kind(layout, e).as_bytes()).with_context(context)?;
            } else {
                write_value(&mut w, &mut buffer, c.read.value(e)).with_context(context)?;
            }
        }
        w.write_record(None::<&[u8]>).with_context(context)?;
    }
    w.flush().with_context(context)
}
