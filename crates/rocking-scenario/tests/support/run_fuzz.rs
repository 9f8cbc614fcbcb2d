// What the `run` fuzz target does with one input, shared by the target
// (`fuzz/fuzz_targets/run.rs`, through `include!`) and the stable replay of
// the kept inputs (`tests/run_fuzz_corpus.rs`). The bytes are decoded into a
// scenario (`scenario_text`): a tower with 0 to 3 blocks on it, an optional
// building, a harmonic or a pulse, a short run; it is read and built as
// `rocking run` does, and run (`replay`). A scenario the parser refuses is
// skipped. A run may refuse the motion (regime switches that do not
// settle, a singular system, a step size too small) with a line naming the
// file, never panic; a run that ends holds finite numbers, and no block
// that did not overturn turned past π/2 on the one below.

/// The fuzzer's bytes, read a few at a time; past their end every read is 0.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }
    /// A number in [0, 1] from two bytes.
    fn unit(&mut self) -> f64 {
        f64::from(u16::from_le_bytes([self.byte(), self.byte()])) / f64::from(u16::MAX)
    }
    /// A number in [lo, hi], evenly spread.
    fn linear(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// A number in [lo, hi] (both > 0), evenly spread on a log scale.
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        lo * (hi / lo).powf(self.unit())
    }
    /// One of `options`.
    fn pick<T: Copy>(&mut self, options: &[T]) -> T {
        options[usize::from(self.byte()) % options.len()]
    }
    /// True one time in `n`.
    fn one_in(&mut self, n: u8) -> bool {
        self.byte().is_multiple_of(n)
    }
}

/// What one input's run did, for the tally of the replay.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Ran {
    /// The parser refused the scenario (out of range: skipped).
    Refused,
    /// The run ended; `overturned`: a block (or the tower) overturned.
    Ended { blocks: usize, overturned: bool },
    /// The run refused the motion: regime switches that do not settle.
    Chattering,
    /// … the equations became singular (Painlevé's paradox of the dynamic normal force).
    Singular,
    /// … the integrator's step size collapsed.
    StepSizeTooSmall,
}

/// The scenario the bytes decode to, as the text of a scenario file, and
/// whether the run keeps its history as well as its summary.
pub fn decode(data: &[u8]) -> (String, bool) {
    use std::fmt::Write;
    let mut b = Bytes(data);
    let mut text = String::from("name = \"fuzz\"\n\n[tower]\n");
    // Squat to slender towers of a few metres to a few tens, light to heavy.
    let mut below = b.log(0.3, 12.0);
    let height = b.log(0.5, 60.0);
    let _ = writeln!(text, "width = {below:?}\nheight = {height:?}\nmass = {:?}", b.log(1e2, 1e7));
    if b.one_in(4) {
        let _ = writeln!(text, "section = \"hollow\"\nwall_thickness = {:?}", below * b.linear(0.02, 0.49));
    }
    let blocks = b.byte() % 4;
    for k in 0..blocks {
        // Every other block as wide as the one below: equal widths are the edge of the rule.
        let width = if b.one_in(3) { below } else { below * b.linear(0.05, 1.0) };
        below = width;
        let _ = writeln!(
            text,
            "\n[[block]]\nname = \"b{}\"\nwidth = {width:?}\nheight = {:?}\nmass = {:?}",
            k + 2,
            b.log(0.1, 20.0),
            b.log(10.0, 1e6)
        );
        if b.one_in(4) {
            let _ = writeln!(text, "section = \"hollow\"\nwall_thickness = {:?}", width * b.linear(0.02, 0.49));
        }
    }
    if !b.byte().is_multiple_of(3) {
        let mu_static = b.linear(0.0, 1.5);
        let _ = writeln!(
            text,
            "\n[building]\nmass = {:?}\nmu_static = {mu_static:?}\nmu_kinetic = {:?}\nnormal_force = \"{}\"",
            b.log(1e3, 1e8),
            mu_static * b.unit(),
            b.pick(&["constant", "dynamic"])
        );
    }
    let kind = b.pick(&["harmonic", "sine-pulse", "cosine-pulse", "rectangular-pulse", "ricker", "none"]);
    let _ = writeln!(text, "\n[ground]\ntype = \"{kind}\"");
    match kind {
        "harmonic" => {
            let _ = writeln!(
                text,
                "amplitude = {:?}\nfrequency = {:?}\nphase = {:?}",
                b.linear(0.0, 4.0),
                b.log(0.5, 20.0),
                b.linear(0.0, std::f64::consts::TAU)
            );
            if b.one_in(2) {
                let _ = writeln!(text, "duration = {:?}", b.log(0.05, 3.0));
            }
        }
        "rectangular-pulse" => {
            let _ = writeln!(text, "amplitude = {:?}\nduration = {:?}", b.linear(-4.0, 4.0), b.log(0.01, 3.0));
        }
        "none" => {}
        _ => {
            let _ = writeln!(text, "amplitude = {:?}\nfrequency = {:?}", b.linear(-4.0, 4.0), b.log(0.5, 20.0));
        }
    }
    if b.one_in(4) {
        let _ = writeln!(
            text,
            "\n[initial]\ntheta_over_alpha = {:?}\ntheta_dot = {:?}",
            b.linear(-1.2, 1.2),
            b.linear(-0.5, 0.5)
        );
    }
    let _ = writeln!(text, "\n[simulation]\nduration = {:?}\nrtol = {:?}", b.log(0.01, 3.0), b.log(1e-10, 1e-6));
    let history = b.byte() % 2 == 1;
    (text, history)
}

/// Decodes one fuzz input, runs it, and checks what the run gives back.
pub fn replay(data: &[u8]) -> Ran {
    use rocking_scenario::{ErrorKind, RunOptions, Scenario};
    use std::f64::consts::FRAC_PI_2;
    let (text, history) = decode(data);
    let origin = std::path::Path::new("fuzz.toml");
    let Ok(scenario) = Scenario::from_toml_str(&text, origin) else {
        return Ran::Refused;
    };
    let Ok(case) = scenario.build() else { return Ran::Refused };
    let options = if history { RunOptions::ALL } else { RunOptions::SUMMARY };
    let outcome = match case.run(options) {
        Ok(outcome) => outcome,
        Err(e) => {
            let line = e.to_string();
            assert!(line.starts_with("fuzz.toml: ") && !line.contains('\n'), "{line}\n{text}");
            return match e.kind() {
                ErrorKind::Simulation(rocking::Error::Chattering { .. }) => Ran::Chattering,
                ErrorKind::Simulation(rocking::Error::Singular { .. }) => Ran::Singular,
                ErrorKind::Simulation(rocking::Error::StepSizeTooSmall { .. }) => Ran::StepSizeTooSmall,
                // The integrator's tolerances are checked when the run starts.
                ErrorKind::Invalid(_) if e.key() == Some("simulation.rtol") => Ran::Refused,
                _ => panic!("a run failed unexpectedly: {line}\n{text}"),
            };
        }
    };
    let s = &outcome.summary;
    let duration = case.settings.duration;
    let finite = [
        s.theta_range.0,
        s.theta_range.1,
        s.max_abs_slip,
        s.final_slip,
        s.max_top_displacement,
        s.max_top_abs_acceleration,
        s.end_time,
    ];
    assert!(finite.iter().all(|v| v.is_finite()), "{s:?}\n{text}");
    assert!(s.time_in_motion.iter().all(|v| v.is_finite() && *v >= 0.0), "{s:?}\n{text}");
    // Infinite once the pivot's normal force reached zero, never NaN.
    assert!(!s.max_pivot_friction_demand.is_nan() && s.max_pivot_friction_demand >= 0.0, "{s:?}\n{text}");
    // The run ends at its duration, or earlier where something overturned.
    assert!(
        s.end_time <= duration && (s.end_time >= duration || s.overturned() || s.stack.is_some_and(|st| st.overturned_block.is_some())),
        "{s:?}\n{text}"
    );
    // The time in each motion adds up to the run's (to the rounding of a sum of steps).
    let total: f64 = s.time_in_motion.iter().sum();
    assert!((total - s.end_time).abs() <= 1e-9 * duration.max(1.0), "{total} != {}\n{text}", s.end_time);
    for t in [s.first_uplift_time, s.first_slip_time, s.overturn_time].into_iter().flatten() {
        assert!((0.0..=s.end_time).contains(&t), "{t}: {s:?}\n{text}");
    }
    let overturned = s.overturned() || s.stack.is_some_and(|st| st.overturned_block.is_some());
    let mut blocks = 0;
    // The tower's |θ| and each block's: below π/2 unless that one overturned.
    let tower_overturned = s.overturned();
    if !tower_overturned {
        assert!(s.max_abs_theta() <= FRAC_PI_2, "tower: {s:?}\n{text}");
    }
    if let Some(stack) = &s.stack {
        // Infinite where a seat would have had to pull (the blocks above it thrown up).
        assert!(
            !stack.max_seat_impulse_ratio.is_nan() && stack.max_seat_impulse_ratio >= 0.0,
            "{stack:?}\n{text}"
        );
        blocks = stack.blocks().len();
        for (k, block) in std::iter::once(stack.tower()).chain(stack.blocks()).enumerate() {
            let values = [block.max_abs_theta, block.theta_range.0, block.theta_range.1];
            assert!(values.iter().all(|v| v.is_finite()), "block {k}: {block:?}\n{text}");
            assert!(
                !block.max_friction_demand.is_nan() && block.max_friction_demand >= 0.0,
                "block {k}: {block:?}\n{text}"
            );
            if stack.overturned_block != Some(k) {
                assert!(block.max_abs_theta <= FRAC_PI_2, "block {k}: {block:?}\n{text}");
            }
        }
    }
    if let Some(history) = &outcome.history {
        for row in &history.samples {
            let mut values = vec![row.t, row.ground_acc, row.state.theta, row.state.theta_dot, row.state.slip, row.state.slip_vel];
            values.extend([row.theta_ddot, row.slip_acc, row.top_dx, row.top_abs_acc]);
            if let Some(st) = row.stack {
                values.extend(st.theta.iter().chain(&st.theta_dot));
            }
            assert!(values.iter().all(|v| v.is_finite()), "history at t = {}: {row:?}\n{text}", row.t);
        }
    }
    Ran::Ended { blocks, overturned }
}
