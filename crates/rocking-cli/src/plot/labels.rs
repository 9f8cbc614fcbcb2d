//! Names, symbols and units of the scenario keys a sweep varies, for axis
//! labels and legends, read from the key descriptions
//! (`rocking_scenario::SCENARIO_KEYS`, docs/src/reference/keys.md).

use rocking_scenario::describe_key;

/// The axis description of a swept key: `ground frequency (Hz)`; an unknown key as it is.
pub fn axis(key: &str) -> String {
    match describe_key(key) {
        Some(k) if k.doc.unit.is_empty() => k.label(),
        Some(k) => format!("{} ({})", k.label(), k.doc.unit),
        None => key.to_string(),
    }
}

/// One value of a swept key: `A = 0.5 g`, `μs = 1.25`; an unknown key as `key = value`.
pub fn value(key: &str, value: &str) -> String {
    match describe_key(key) {
        Some(k) if k.doc.unit.is_empty() => format!("{} = {value}", k.symbol()),
        Some(k) => format!("{} = {value} {}", k.symbol(), k.doc.unit),
        None => format!("{key} = {value}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rocking_scenario::SWEEPABLE_KEYS;

    /// A hand-checked sample, one key of each section and of the vertical
    /// motion, against the key reference's units and symbols.
    #[test]
    fn known_and_unknown_keys() {
        assert_eq!(axis("ground.frequency"), "ground frequency (Hz)");
        assert_eq!(axis("building.mu_static"), "static friction μs");
        assert_eq!(axis("tower.density"), "tower density (kg/m³)");
        assert_eq!(axis("initial.theta_dot"), "initial angular velocity (rad/s)");
        assert_eq!(axis("simulation.g"), "gravity g (m/s²)");
        assert_eq!(axis("ground.vertical.amplitude"), "vertical ground amplitude (g)");
        assert_eq!(axis("tower.nonsense"), "tower.nonsense");
        assert_eq!(value("ground.amplitude", "0.5"), "A = 0.5 g");
        assert_eq!(value("building.mu_kinetic", "1"), "μk = 1");
        assert_eq!(value("tower.alpha", "0.25"), "α = 0.25 rad");
        assert_eq!(value("ground.vertical.frequency", "8"), "f (vertical) = 8 Hz");
        assert_eq!(value("x.y", "z"), "x.y = z");
    }

    /// Every key a sweep can vary is described, so has its own words and
    /// symbol on a plot, with the unit of its description: none falls back
    /// to the bare key.
    #[test]
    fn every_sweepable_key_is_labelled() {
        for key in SWEEPABLE_KEYS.iter() {
            let Some(described) = describe_key(key) else {
                panic!("{key} is not described")
            };
            let (axis, value) = (axis(key), value(key, "1"));
            let unit = described.doc.unit;
            assert!(
                axis != *key && value.starts_with(&format!("{} = 1", described.symbol())),
                "{key}: {axis:?}, {value:?}"
            );
            assert!(
                unit.is_empty() || (axis.ends_with(&format!("({unit})")) && value.ends_with(&format!(" {unit}"))),
                "{key}: {axis:?}, {value:?}"
            );
        }
    }
}
