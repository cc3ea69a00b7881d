"""Every plausible request builds, and what it names is there (issue 16).

For every building type: its plain description and three descriptions naming extra rooms and
floors, each over seeds 0..N-1. A run fails when generation raises; a request fails when the
building's record (``program.requests``) says it was honoured but the room is not on the floor it
names (or a not-honoured record gives no reason). Prints failures, per-type figures and the totals.

    PYTHONPATH=python nice -n 10 python benches/python/bench_requests.py            # seeds 0-49
    PYTHONPATH=python python benches/python/bench_requests.py --seeds 5 --types hotel office
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import Counter

from mansion.building import generate_building
from mansion.exceptions import MansionError
from mansion.models.building import Building

#: Per type: the plain description, then three naming extra rooms and floors.
DESCRIPTIONS: dict[str, tuple[str, ...]] = {
    "studio": (
        "a studio apartment",
        "a studio flat with a home office",
        "a small studio with a walk-in closet and a reading nook",
        "a bedsit with a laundry room on the ground floor",
    ),
    "family_apartment": (
        "a family apartment",
        "a three-bedroom flat with a home office and a home cinema",
        "a family apartment with two bathrooms and a playroom",
        "an apartment with a laundry room and a guest bedroom",
    ),
    "townhouse": (
        "a townhouse",
        "a three-storey townhouse with a home office on the top floor",
        "a two-storey terraced house with a home cinema on the ground floor",
        "a townhouse with a kitchen downstairs and a guest bedroom upstairs",
    ),
    "villa": (
        "a villa",
        "a two-storey villa with a home cinema on the ground floor",
        "a villa with a library on the upper floor and a wine cellar",
        "a three-storey villa with a home gym on the top floor and a sauna",
    ),
    "apartment_block": (
        "an apartment block",
        "a five-storey apartment building with a gym on the ground floor",
        "a block of flats with a laundry room on the ground floor",
        "a four-storey apartment block with a bike store next to the entrance",
    ),
    "office": (
        "an office building",
        "a four-storey office building with a cafe on the ground floor",
        "a two-storey office building with a staff kitchen on the upper floor",
        "a three-storey office with two meeting rooms on the second floor and a server room",
    ),
    "hospital": (
        "a hospital",
        "a five-storey hospital with two operating theatres on the top floor",
        "a three-storey hospital with a pharmacy on the ground floor and a laboratory on the second floor",
        "a hospital with a chapel on the ground floor",
    ),
    "school": (
        "a school",
        "a three-storey school with a gym on the ground floor",
        "a two-storey school with a library on the upper floor and a music room",
        "a school with two science labs on the second floor",
    ),
    "kindergarten": (
        "a kindergarten",
        "a two-storey kindergarten with a nap room on the first floor",
        "a kindergarten with a playroom and a nurse's office",
        "a two-storey kindergarten with a kitchen on the ground floor and a quiet room upstairs",
    ),
    "supermarket": (
        "a supermarket",
        "a supermarket with a bakery next to the entrance",
        "a two-storey supermarket with a staff canteen on the upper floor",
        "a supermarket with a pharmacy on the ground floor",
    ),
    "library": (
        "a library",
        "a two-storey library with a children's reading room on the ground floor",
        "a three-storey library with a cafe on the ground floor and a computer room on the top floor",
        "a library with a lecture hall",
    ),
    "restaurant": (
        "a restaurant",
        "a two-storey restaurant with a bar on the upper floor",
        "a restaurant with a private dining room and a bakery",
        "a two-storey restaurant with a wine cellar and a staff room upstairs",
    ),
    "hotel": (
        "a hotel",
        "a two-storey hotel with a restaurant on the upper floor",
        "a four-storey hotel with a gym on the top floor and a laundry room on the ground floor",
        "a hotel with a spa and a conference room on the first floor",
    ),
    "shopping_mall": (
        "a shopping mall",
        "a three-storey shopping mall with a food court on the top floor",
        "a mall with a cinema on the second floor",
        "a two-storey shopping centre with a pharmacy and a supermarket on the ground floor",
    ),
}


def request_problems(building: Building) -> list[str]:
    """Requests the building gets wrong: honoured but missing from a floor it names, or not
    honoured without a reason."""
    out = []
    for r in building.program.requests:
        if not r.honoured:
            if not r.reason:
                out.append(f"{r.phrase!r}: not honoured, no reason")
            continue
        for index in r.built_on or []:
            types = [n.room_type for n in building.floors[index].graph.nodes]
            ids = {n.id for n in building.floors[index].graph.nodes}
            if types.count(r.room_type) < r.count:
                out.append(f"{r.phrase!r}: honoured but floor {index} has {types.count(r.room_type)} {r.room_type}")
            missing = [i for i in r.room_ids if i not in ids and building.floors[index].copy_of is None]
            if missing and len(r.built_on) == 1:
                out.append(f"{r.phrase!r}: rooms {missing} not on floor {index}")
        if r.floors and sorted(r.floors) != sorted(r.built_on):
            out.append(f"{r.phrase!r}: asked on floors {r.floors}, built on {r.built_on}")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=50)
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--types", nargs="*", default=list(DESCRIPTIONS))
    args = ap.parse_args(argv)
    runs = fails = requests = unmet = wrong = 0
    by_type: dict[str, Counter[str]] = {}
    start = time.perf_counter()
    for kind in args.types:
        c = by_type.setdefault(kind, Counter())
        for text in DESCRIPTIONS[kind]:
            for seed in range(args.first, args.first + args.seeds):
                runs += 1
                c["runs"] += 1
                try:
                    b = generate_building(text, seed=seed)
                except MansionError as exc:
                    fails += 1
                    c["fails"] += 1
                    print(f"FAIL {kind} seed {seed} {text!r}: {type(exc).__name__}: {exc}", flush=True)
                    continue
                if b.program.building_type != kind:
                    print(f"TYPE {kind} seed {seed} {text!r}: read as {b.program.building_type}", flush=True)
                requests += len(b.program.requests)
                c["requests"] += len(b.program.requests)
                n_unmet = sum(not r.honoured for r in b.program.requests)
                unmet += n_unmet
                c["not honoured"] += n_unmet
                for p in request_problems(b):
                    wrong += 1
                    c["wrong"] += 1
                    print(f"WRONG {kind} seed {seed} {text!r}: {p}", flush=True)
        print(
            f"{kind:17s} {c['runs']:4d} runs  {c['fails']:3d} failed  {c['requests']:4d} requests  "
            f"{c['not honoured']:3d} not honoured (with reason)  {c['wrong']:3d} wrong", flush=True,
        )
    print(
        f"\n{runs} buildings in {time.perf_counter() - start:.0f} s: {fails} failed; "
        f"{requests} requests, {unmet} not honoured (each with its reason), {wrong} wrong records"
    )
    return 1 if fails or wrong else 0


if __name__ == "__main__":
    sys.exit(main())
