//! Benchmark cases shared by the criterion benches (and usable from tests): a 7-room plan on a
//! 64×64 grid, as in the paper's T2D measurements, and a 500 m² office floor with about 20 rooms.

use mansion_core::raster::{CoreSpec, FootprintSpec};
use mansion_core::solve::{EdgeSpec, GraphSpec, NodeSpec, SolveOptions};

fn node(id: &str, kind: &str, area: f64) -> NodeSpec {
    NodeSpec {
        id: id.into(),
        kind: kind.into(),
        area,
        room_type: None,
        min_width: None,
        min_area: None,
        clear_width: None,
        max_aspect: None,
    }
}

fn edges(pairs: &[(&str, &str)]) -> Vec<EdgeSpec> {
    pairs
        .iter()
        .map(|(a, b)| EdgeSpec {
            source: (*a).into(),
            target: (*b).into(),
            kind: "access".into(),
        })
        .collect()
}

/// A T2D-like apartment: a 16 × 16 m L-shaped outline at 0.25 m cells (a 64 × 64 grid), seven
/// rooms, living room as hub.
pub fn t2d_like() -> (GraphSpec, FootprintSpec, SolveOptions) {
    let graph = GraphSpec {
        nodes: vec![
            node("living", "main", 62.0),
            node("kitchen", "area", 18.0),
            node("bath", "area", 9.0),
            node("master", "area", 32.0),
            node("bed2", "area", 26.0),
            node("bed3", "area", 22.0),
            node("balcony", "area", 11.0),
        ],
        edges: edges(&[
            ("living", "kitchen"),
            ("living", "bath"),
            ("living", "master"),
            ("living", "bed2"),
            ("living", "bed3"),
            ("living", "balcony"),
            ("master", "bath"),
        ]),
    };
    let fp = FootprintSpec {
        polygon: vec![
            [0.0, 0.0],
            [16.0, 0.0],
            [16.0, 11.0],
            [11.0, 11.0],
            [11.0, 16.0],
            [0.0, 16.0],
        ],
        ..Default::default()
    };
    let opts = SolveOptions {
        cell_size: 0.25,
        min_contact: 1.0,
        ..Default::default()
    };
    (graph, fp, opts)
}

/// A 500 m² office floor (25 × 20 m, 0.5 m cells) with a stair and an elevator core, a corridor hub
/// and 20 rooms.
pub fn office() -> (GraphSpec, FootprintSpec, SolveOptions) {
    let mut nodes = vec![
        node("corridor", "main", 70.0),
        node("stair", "stair", 0.0),
        node("lift", "elevator", 0.0),
        node("reception", "area", 30.0),
        node("open_office_a", "area", 60.0),
        node("open_office_b", "area", 55.0),
        node("meeting_1", "area", 20.0),
        node("meeting_2", "area", 16.0),
        node("kitchen", "area", 18.0),
        node("toilet_m", "area", 9.0),
        node("toilet_f", "area", 9.0),
        node("server", "area", 8.0),
        node("storage", "area", 8.0),
        node("office_1", "area", 12.0),
        node("office_2", "area", 12.0),
        node("office_3", "area", 12.0),
        node("office_4", "area", 12.0),
        node("phone_1", "area", 5.0),
        node("phone_2", "area", 5.0),
        node("copy", "area", 7.0),
        node("waiting", "area", 10.0),
    ];
    nodes.iter_mut().for_each(|n| {
        n.room_type = Some(
            n.id.trim_end_matches(char::is_numeric)
                .trim_end_matches('_')
                .to_string(),
        )
    });
    let graph = GraphSpec {
        nodes,
        edges: edges(&[
            ("corridor", "stair"),
            ("corridor", "lift"),
            ("corridor", "reception"),
            ("corridor", "open_office_a"),
            ("corridor", "open_office_b"),
            ("corridor", "meeting_1"),
            ("corridor", "kitchen"),
            ("corridor", "toilet_m"),
            ("corridor", "toilet_f"),
            ("corridor", "office_1"),
            ("corridor", "office_2"),
            ("corridor", "office_3"),
            ("corridor", "office_4"),
            ("corridor", "storage"),
            ("reception", "waiting"),
            ("open_office_a", "meeting_2"),
            ("open_office_a", "phone_1"),
            ("open_office_b", "phone_2"),
            ("open_office_b", "copy"),
            ("storage", "server"),
        ]),
    };
    let fp = FootprintSpec {
        polygon: vec![[0.0, 0.0], [25.0, 0.0], [25.0, 20.0], [0.0, 20.0]],
        cores: vec![
            CoreSpec {
                id: "stair".into(),
                kind: "stair".into(),
                x: [0.0, 3.0],
                y: [0.0, 5.0],
            },
            CoreSpec {
                id: "lift".into(),
                kind: "elevator".into(),
                x: [22.5, 25.0],
                y: [17.5, 20.0],
            },
        ],
        ..Default::default()
    };
    (graph, fp, SolveOptions::default())
}

/// A case with width rules: every room of `graph` at least `room` metres wide, the hub at least
/// `hub` metres, and the floor-wide rule of `floor` cells.
pub fn with_widths(
    (mut graph, fp, opts): (GraphSpec, FootprintSpec, SolveOptions),
    room: f64,
    hub: f64,
    floor: usize,
) -> (GraphSpec, FootprintSpec, SolveOptions) {
    for n in graph.nodes.iter_mut() {
        n.min_width = match n.kind.as_str() {
            "main" => Some(hub),
            "stair" | "elevator" => None,
            _ => Some(room),
        };
    }
    let opts = SolveOptions {
        min_width: Some(floor),
        ..opts
    };
    (graph, fp, opts)
}

/// Design minimums on every room of `graph` (its planned area, a clear width of 2.0 m for
/// rooms of 12 m² and more and 1.5 m below, boxes at most 3× longer than wide; none on the hub
/// and cores), with the repair and the rounds' rebalance on or off.
pub fn with_minimums(
    (mut graph, fp, opts): (GraphSpec, FootprintSpec, SolveOptions),
    repair: bool,
) -> (GraphSpec, FootprintSpec, SolveOptions) {
    for n in graph.nodes.iter_mut() {
        if n.kind == "area" {
            n.min_area = Some(n.area);
            n.clear_width = Some(if n.area >= 12.0 { 2.0 } else { 1.5 });
            n.max_aspect = Some(3.0);
        }
    }
    (
        graph,
        fp,
        SolveOptions {
            repair,
            rebalance: repair,
            ..opts
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use mansion_core::seedplan::HeuristicPlanner;
    use mansion_core::solve::solve_floor;

    #[test]
    fn both_cases_solve() {
        for (g, f, o) in [
            t2d_like(),
            office(),
            with_widths(office(), 1.0, 1.5, 2),
            with_widths(t2d_like(), 1.0, 1.5, 4),
        ] {
            let t = std::time::Instant::now();
            match solve_floor(&g, &f, &o, &mut HeuristicPlanner) {
                Ok(s) => {
                    eprintln!("{:?}", t.elapsed());
                    for r in &s.diagnostics.rounds {
                        eprintln!(
                            "{} {:?} retry {:?} cand {} {:.4}s rejected {:?}",
                            r.parent, r.children, r.retry, r.candidates, r.seconds, r.rejected
                        );
                    }
                }
                Err(e) => panic!("{e}"),
            }
        }
    }
}
