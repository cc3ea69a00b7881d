//! Criterion benches of object placement: the paper's library (18 × 14 m polygon, one door)
//! furnished with wall shelf runs, reading tables with chairs, shelf stacks and study desks
//! (asset sizes typical of AI2-THOR), and one reachability flood fill on its 5 cm grid.

use criterion::{criterion_group, criterion_main, Criterion};
use mansion_core::place::geometry::{frame, Footprint, Room, Wall};
use mansion_core::place::place_room;
use mansion_core::place::reach::ReachGrid;
use mansion_core::place::spec::{
    DoorSpec, ItemSpec, PlaceOptions, PlacementRequest, Side, SmallSpec, Structure, Tag,
};
use std::hint::black_box;

const LIBRARY: [[f64; 2]; 8] = [
    [0.0, 0.0],
    [18.0, 0.0],
    [18.0, 14.0],
    [12.0, 14.0],
    [12.0, 9.0],
    [6.0, 9.0],
    [6.0, 14.0],
    [0.0, 14.0],
];

/// A bench item: shelves and desks have a front, and everything offers two books for its top.
fn item(id: &str, ty: &str, size: [f64; 3], tag: Tag, structure: Structure) -> ItemSpec {
    let book = SmallSpec {
        object_type: "Book".into(),
        asset_id: "Book_1".into(),
        size: [0.2, 0.25, 0.04],
    };
    ItemSpec {
        has_front: ty == "ShelvingUnit" || ty == "Desk",
        small: vec![book; 2],
        ..ItemSpec::new(id, ty, size, tag, structure)
    }
}

fn library() -> PlacementRequest {
    let shelf = [1.1, 0.42, 2.0];
    let mut items = vec![
        item(
            "desk",
            "Desk",
            [1.4, 0.7, 0.75],
            Tag::Edge,
            Structure::Single,
        ),
        item(
            "desk_chair",
            "Chair",
            [0.5, 0.5, 0.9],
            Tag::Edge,
            Structure::paired("desk", Side::Front, 1, 0.3),
        ),
    ];
    for k in 0..8 {
        let id = format!("wall_shelves{k}");
        items.push(item(
            &id,
            "ShelvingUnit",
            shelf,
            Tag::Edge,
            Structure::matrix(1, 8 - (k % 4), 0.8, 0.02),
        ));
    }
    let middle: [(&str, &str, [f64; 3], Structure); 5] = [
        (
            "reading_table",
            "DiningTable",
            [1.2, 0.9, 0.75],
            Structure::matrix(2, 3, 0.75, 0.75),
        ),
        (
            "reader",
            "Chair",
            [0.45, 0.45, 0.9],
            Structure::paired("reading_table", Side::Around, 4, 0.3),
        ),
        (
            "stack",
            "ShelvingUnit",
            shelf,
            Structure::matrix(2, 4, 0.8, 0.02),
        ),
        (
            "study",
            "Desk",
            [1.0, 0.55, 0.75],
            Structure::matrix(1, 4, 0.7, 0.6),
        ),
        (
            "study_chair",
            "Chair",
            [0.45, 0.45, 0.9],
            Structure::paired("study", Side::Front, 1, 0.45),
        ),
    ];
    for (id, ty, size, structure) in middle {
        items.push(item(id, ty, size, Tag::Middle, structure));
    }
    PlacementRequest {
        room_id: "library".into(),
        polygon: LIBRARY.to_vec(),
        doors: vec![DoorSpec::swinging([8.5, 0.0], [9.5, 0.0])],
        keep_clear: Vec::new(),
        items,
        options: PlaceOptions::default(),
    }
}

fn bench(c: &mut Criterion) {
    let req = library();
    let placed = place_room(&req).expect("the library is furnishable");
    assert!(
        placed.objects.len() > 54,
        "{} objects",
        placed.objects.len()
    );
    let mut g = c.benchmark_group("placement");
    g.sample_size(20);
    g.bench_function("library_place_room", |b| {
        b.iter(|| place_room(black_box(&req)).expect("furnishable"))
    });
    // one flood fill of the furnished library's free space
    let room = Room::new("library", &LIBRARY).expect("room");
    let walls: Vec<Wall> = room
        .walls
        .iter()
        .flat_map(|w| {
            if w.a == [0.0, 0.0] {
                vec![
                    Wall {
                        a: [0.0, 0.0],
                        b: [8.5, 0.0],
                    },
                    Wall {
                        a: [9.5, 0.0],
                        b: [18.0, 0.0],
                    },
                ]
            } else {
                vec![*w]
            }
        })
        .collect();
    let zone = Footprint::new(frame([9.0, 0.5], 0.0), 1.0, 1.0);
    let mut grid =
        ReachGrid::new("library", &room, &walls, &[zone], 0.25, 0.5, 0.05).expect("grid");
    for o in &placed.objects {
        grid.block(&Footprint::new(
            frame(o.center, o.yaw),
            o.size[0],
            o.size[1],
        ));
    }
    g.bench_function("library_flood_fill", |b| b.iter(|| grid.flood()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
