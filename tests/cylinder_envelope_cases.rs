//! The cylinder's envelope campaign (`validation/cylinder/envelope.toml`, issue 45 item 5) is a
//! case list the suite reads, and every case that calibrates or holds out the envelope is inside
//! it (a case outside would be "not judged" and measure nothing the bounds speak for); the
//! "probe-" cases are beyond its a/R on purpose.

use microslip::problems::cylinder::closed_form::{Cylinder, CylinderParams};
use microslip::suite::Ladder;
use microslip::suite::cases::resolve;

const CASES: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/validation/cylinder/envelope.toml"
);

#[test]
fn the_envelope_campaign_is_a_suite_case_list_inside_the_envelope() {
    let cases = resolve(Some(CASES), Ladder::Full).unwrap();
    assert!(cases.len() >= 9, "{}", cases.len());
    let (mut calibration, mut held_out) = (0, 0);
    for case in &cases {
        let mut params = CylinderParams::STEEL_PAD;
        for assignment in &case.assignments {
            let (key, value) = assignment.split_once('=').unwrap();
            let value: f64 = value.parse().unwrap();
            match key {
                "R" => params.radius = value,
                "P" => params.normal_load = value,
                "KT" => params.tangential_stiffness = value,
                "Q" => {}
                other => panic!("{}: unexpected {other}", case.name),
            }
        }
        let v = Cylinder::new(params).unwrap().validity();
        if case.name.starts_with("probe-") {
            // Beyond the envelope's a/R on purpose: how far the half-plane answer departs.
            assert!(
                v.outside_because.is_some_and(|why| why.contains("a/R")),
                "{}",
                case.name
            );
            continue;
        }
        assert!(
            v.outside_because.is_none(),
            "{}: K_T a/E* {}, a/R {}: {:?}",
            case.name,
            v.stiffness_group,
            v.half_width_over_radius,
            v.outside_because
        );
        calibration += usize::from(case.name.starts_with("cal-"));
        held_out += usize::from(case.name.starts_with("hold-"));
    }
    assert!(calibration >= 4, "{calibration}");
    assert!(held_out >= 2, "{held_out}");
}
