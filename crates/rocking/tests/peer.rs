//! Against a second implementation: `scripts/peer/scipy_peer.py` of the
//! repository, written from the model (SciPy's DOP853 with terminal events and a restart at every
//! impact), on a 3 × 3 grid of harmonic inputs for the 0.5 m × 2 m block over
//! 10 s, both at rtol 1e-10. The reference values were printed by
//!
//! ```text
//! python3 scripts/peer/scipy_peer.py 0.5 2.0 10 1e-10 "0.3,0.5,1.0" "1.0,2.0,4.0"
//! ```
//!
//! (SciPy 1.17.1). An overturned case reports `π/2 / α`.

mod common;

use common::*;
use rocking::{GroundMotion, Harmonic, Initial, Settings};

/// (amplitude in g, frequency in Hz, max θ/α, impacts, overturned).
const PEER: [(f64, f64, f64, u64, bool); 9] = [
    (0.3, 1.0, 6.411971992766762, 2, true),
    (0.3, 2.0, 0.21058300329651253, 39, false),
    (0.3, 4.0, 0.048888255546628144, 79, false),
    (0.5, 1.0, 6.411971992766762, 5, true),
    (0.5, 2.0, 0.3161711521544367, 39, false),
    (0.5, 4.0, 0.07974051819181191, 79, false),
    (1.0, 1.0, 6.411971992766762, 0, true),
    (1.0, 2.0, 6.411971992766762, 5, true),
    (1.0, 4.0, 0.19918083330805386, 30, false),
];

/// Same peaks to 1e-6 relative (the issue's figure; both integrate to 1e-10,
/// so agreement is far closer), the same impacts and the same verdict.
#[test]
fn agrees_with_the_scipy_peer() {
    let tower = block();
    let model = fixed(tower);
    for (amplitude, frequency, ratio, impacts, overturned) in PEER {
        let ground = GroundMotion::Harmonic(Harmonic::new(amplitude * G, frequency, 10.0, 0.0).unwrap());
        let s = run(
            &model,
            &ground,
            Initial::default(),
            &Settings {
                duration: 10.0,
                rtol: 1e-10,
                atol: 1e-12,
            },
        );
        let ours = s.max_abs_theta() / tower.alpha();
        assert!((ours - ratio).abs() <= 1e-6 * ratio, "A = {amplitude} g, f = {frequency} Hz: {ours} vs {ratio}");
        assert_eq!(s.impacts, impacts, "A = {amplitude} g, f = {frequency} Hz");
        assert_eq!(s.overturned(), overturned, "A = {amplitude} g, f = {frequency} Hz");
    }
}
