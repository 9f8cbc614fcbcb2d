//! Names, symbols and units of the scenario keys a sweep varies, for axis
//! labels and legends (docs/src/reference/keys.md).

/// `(description, symbol, unit)` of the keys with a known meaning.
const KEYS: &[(&str, &str, &str, &str)] = &[
    ("ground.frequency", "ground frequency", "f", "Hz"),
    ("ground.amplitude", "ground amplitude", "A", "g"),
    ("ground.amplitude_ratio", "amplitude ratio a_p/(g tan α)", "a_p/(g tan α)", ""),
    ("ground.frequency_ratio", "frequency ratio ω/p", "ω/p", ""),
    ("ground.duration", "shaking duration", "duration", "s"),
    ("ground.phase", "ground phase", "φ", "rad"),
    ("ground.scale", "record scale", "scale", ""),
    ("ground.t0", "pulse centre t0", "t0", "s"),
    ("building.mu_static", "static friction μs", "μs", ""),
    ("building.mu_kinetic", "kinetic friction μk", "μk", ""),
    ("building.mass", "building mass m1", "m1", "kg"),
    ("tower.width", "tower width B", "B", "m"),
    ("tower.height", "tower height H", "H", "m"),
    ("tower.depth", "tower depth", "depth", "m"),
    ("tower.mass", "tower mass m2", "m2", "kg"),
    ("tower.density", "tower density", "ρ", "kg/m³"),
    ("tower.wall_thickness", "tower wall thickness", "t", "m"),
    ("tower.restitution", "restitution r", "r", ""),
    ("initial.theta", "initial rotation θ0", "θ0", "rad"),
    ("initial.theta_over_alpha", "initial rotation θ0/α", "θ0/α", ""),
    ("initial.theta_dot", "initial angular velocity", "θ̇0", "rad/s"),
    ("simulation.g", "gravity g", "g", "m/s²"),
    ("simulation.duration", "duration", "duration", "s"),
];

fn lookup(key: &str) -> Option<(&'static str, &'static str, &'static str)> {
    KEYS.iter().find(|k| k.0 == key).map(|k| (k.1, k.2, k.3))
}

/// The axis description of a swept key: `ground frequency (Hz)`; an unknown key as it is.
pub fn axis(key: &str) -> String {
    match lookup(key) {
        Some((name, _, "")) => name.to_string(),
        Some((name, _, unit)) => format!("{name} ({unit})"),
        None => key.to_string(),
    }
}

/// One value of a swept key: `A = 0.5 g`, `μs = 1.25`; an unknown key as `key = value`.
pub fn value(key: &str, value: &str) -> String {
    match lookup(key) {
        Some((_, symbol, "")) => format!("{symbol} = {value}"),
        Some((_, symbol, unit)) => format!("{symbol} = {value} {unit}"),
        None => format!("{key} = {value}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_and_unknown_keys() {
        assert_eq!(axis("ground.frequency"), "ground frequency (Hz)");
        assert_eq!(axis("building.mu_static"), "static friction μs");
        assert_eq!(axis("tower.points"), "tower.points");
        assert_eq!(value("ground.amplitude", "0.5"), "A = 0.5 g");
        assert_eq!(value("building.mu_kinetic", "1"), "μk = 1");
        assert_eq!(value("x.y", "z"), "x.y = z");
    }
}
