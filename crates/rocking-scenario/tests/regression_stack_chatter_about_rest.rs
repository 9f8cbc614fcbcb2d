//! A stack of three blocks on a light tower (found by the `run` fuzz target:
//! a slender block of 1 t carrying 65 t on a 1.3 t tower, after a 0.01 s
//! pulse of 4 g) never ended in practice: from t = 0.72 s, as the tower rocked
//! freely, its blocks took turns to lift and land again at angular
//! velocities about the rest threshold (1e-9 rad/s), one lifting as another
//! landed, the events some 1e-8 s apart and their rotations 1e-17 rad or
//! less; the 3 s run would have taken hours. Ten thousand regime switches
//! within a millisecond now stop a stacked run with the error of switches
//! that do not settle, at the instant they piled up.

use rocking::{Event, EventKind, Flow, Halt, Observer, REST_ANGULAR_VELOCITY};
use rocking_scenario::{ErrorKind, RunOptions, Scenario};
use std::path::Path;

const SCENARIO: &str = r#"
[tower]
width = 4.920481246832232
height = 45.07245030878726
mass = 1278.3817528592115

[[block]]
name = "b2"
width = 2.2031119730466338
height = 19.34479230213452
mass = 1000.0000000000002

[[block]]
name = "b3"
width = 2.2031119730466338
height = 1.1836331039310268
mass = 31926.997883635373

[[block]]
name = "b4"
width = 2.2031119730466338
height = 20.0
mass = 32779.5018935352
section = "hollow"
wall_thickness = 1.0795248667928505

[ground]
type = "rectangular-pulse"
amplitude = -3.988281071183337
duration = 0.01

[simulation]
duration = 3.0
rtol = 5.829572162760725e-10
"#;

/// Keeps the events, and stops the run past 100,000 of them (the fix stops
/// it at about 10,000 in the last millisecond).
#[derive(Default)]
struct Kept(Vec<Event>);

impl Observer for Kept {
    fn on_event(&mut self, event: &Event) -> Flow {
        self.0.push(*event);
        if self.0.len() > 100_000 {
            return Flow::Break(Halt::Stop);
        }
        Flow::Continue(())
    }
}

#[test]
fn blocks_that_lift_and_land_about_the_rest_threshold_end_the_run() {
    let case = Scenario::from_toml_str(SCENARIO, Path::new("fuzz.toml"))
        .and_then(|s| s.build())
        .expect("a valid scenario");
    let mut kept = Kept::default();
    let error = case.run_observed(RunOptions::SUMMARY, &mut kept).expect_err("the switches do not settle");
    let ErrorKind::Simulation(rocking::Error::Chattering { time, .. }) = *error.kind() else {
        panic!("{error}");
    };
    // Long after the pulse, while the tower rocks freely.
    assert!(time > 0.5 && time < 3.0, "{time}");
    // What piled up: impacts of the blocks above the tower (not the tower's)
    // landing at a few times the rest threshold, within the last millisecond.
    let last: Vec<&Event> = kept.0.iter().rev().filter(|e| e.kind == EventKind::Impact).take(100).collect();
    assert_eq!(last.len(), 100);
    for e in last {
        assert!(e.block > 0 && time - e.time < 1e-3, "{e:?}");
        assert!(e.before.theta_dot.abs() < 10.0 * REST_ANGULAR_VELOCITY, "{e:?}");
    }
}
