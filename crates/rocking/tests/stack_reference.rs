//! Three stacks against the second implementation of the stack in
//! `validation/stack/reference.py` (positions written once, equations derived
//! by SymPy, SciPy's DOP853 with its event finder; it shares no code with
//! this one): a belfry on a rocking shaft on a fixed base, the same on a
//! church that slides, and a slender belfry that overturns while its shaft
//! survives (the stacks of the MuJoCo comparison, `validation/mujoco_stack.py`).
//! The reference's numbers, with its seat condition on the force normal to the
//! shaft's top (`seat="normal"`, this library's), came from
//!
//! ```text
//! cd validation && python -c 'import math; from stack.reference import Stack
//! a_g = lambda t: A * 9.81 * math.sin(2 * math.pi * f * t) if t < 3.0 else 0.0
//! print(Stack([(4.0, 12.0, 1.5e5), BELFRY], building=CHURCH, ground=a_g,
//!             kinks=(3.0,), g=9.81, seat="normal").run(6.0)[2])'
//! ```
//!
//! with each case's amplitude `A` (g), frequency `f` (Hz), `BELFRY` (width,
//! height, mass) and `CHURCH` (`(2e6, μ, μ)`, or `None` for a fixed base),
//! at rtol 1e-10, atol 1e-12 (its default). Tolerances: both integrate to rtol
//! 1e-10 through some fifty impacts, and the reference reads its peaks on a
//! grid of 2e-4 s (an error below `θ̈ (1e-4 s)² ~ 1e-8` rad): peaks to 1e-6
//! relative, instants located by root finding to 1e-8 s, slips to 1e-8 m. The
//! belfry's impacts are not compared: the reference seats an interface below
//! 1e-7 rad/s, this library below 1e-9, so the last tiny impacts differ in
//! number.

use rocking::stack::run::{run, RunSettings, StackRun};
use rocking::stack::{Block, Stack, StackState};
use rocking::{Building, GroundMotion, Harmonic, NormalForce};

const G: f64 = 9.81;

fn stack_run(upper: (f64, f64, f64), mu: Option<f64>, amplitude: f64, frequency: f64) -> (Stack, StackRun) {
    let shaft = Block::solid(1, 4.0, 12.0, 1.5e5).expect("a valid shaft");
    let belfry = Block::solid(2, upper.0, upper.1, upper.2).expect("a valid belfry");
    let building = mu.map(|m| Building::new(2.0e6, m, m, NormalForce::Constant).expect("a valid church"));
    let stack = Stack::new(&[shaft, belfry], building, G).expect("a valid stack");
    let ground = GroundMotion::Harmonic(Harmonic::new(amplitude * G, frequency, 3.0, 0.0).expect("a valid input"));
    let settings = RunSettings {
        duration: 6.0,
        rtol: 1e-10,
        atol: 1e-12,
        sample_interval: 0.005,
    };
    let out = run(&stack, &ground, &StackState::default(), &settings).expect("the run");
    (stack, out)
}

fn close(what: &str, got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "{what}: {got} vs the reference's {want}");
}

fn peaks_and_uplifts(out: &StackRun, peaks: [f64; 2], uplifts: [f64; 2]) {
    for k in 0..2 {
        close(&format!("largest |θ_{}|", k + 1), out.blocks[k].max_abs_theta, peaks[k], 1e-6 * peaks[k]);
        close(
            &format!("first uplift of interface {}", k + 1),
            out.blocks[k].first_uplift_time.expect("an uplift"),
            uplifts[k],
            1e-8,
        );
    }
}

#[test]
fn belfry_on_a_rocking_shaft_on_a_fixed_base() {
    let (_, out) = stack_run((2.4, 6.0, 6.0e4), None, 0.4, 1.0);
    peaks_and_uplifts(&out, [0.03031961044575956, 0.2034600376402572], [0.09912592975736681, 0.5835369191507073]);
    assert_eq!(out.blocks[0].impacts, 11);
    assert!(out.overturned.is_none());
}

#[test]
fn belfry_on_a_rocking_shaft_on_a_sliding_church() {
    let (_, out) = stack_run((2.4, 6.0, 6.0e4), Some(0.4), 0.6, 1.5);
    peaks_and_uplifts(&out, [0.014665678907711198, 0.0673843751458084], [0.042380334215108464, 0.3691753419180641]);
    assert_eq!(out.blocks[0].impacts, 23);
    // The slip is monotone within each slip and stops at an event: its
    // extremes are at the events and the end.
    let largest = out
        .events
        .iter()
        .map(|e| e.before.slip.abs())
        .chain(out.samples.iter().map(|s| s.state.slip.abs()))
        .fold(0.0, f64::max);
    close("largest slip", largest, 0.03135415155293897, 1e-8);
    close("final slip", out.samples.last().expect("samples").state.slip, -0.03047454302763448, 1e-8);
    // The seated belfry through the shaft's impacts on a stuck church: the
    // compound closed form of `stack_core.rs`, here from an impact in the run.
    close("max_seat_impulse_ratio", out.max_seat_impulse_ratio, 0.803835367240204, 1e-12);
}

#[test]
fn slender_belfry_overturns_and_the_shaft_survives() {
    let (_, out) = stack_run((0.8, 4.0, 3.0e4), None, 0.5, 2.0);
    assert_eq!(out.overturned, Some(1));
    close("overturning instant", out.events.last().expect("events").time, 5.240059641774728, 1e-7);
    close("largest |θ_1|", out.blocks[0].max_abs_theta, 0.008706635710582595, 1e-6 * 0.0087);
    close(
        "first uplift of the shaft",
        out.blocks[0].first_uplift_time.expect("an uplift"),
        0.05054127008955253,
        1e-8,
    );
    close(
        "first uplift of the belfry",
        out.blocks[1].first_uplift_time.expect("an uplift"),
        0.032747470108613654,
        1e-8,
    );
    assert_eq!((out.blocks[0].impacts, out.blocks[1].impacts), (23, 5));
}
