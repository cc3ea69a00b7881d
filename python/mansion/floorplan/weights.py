"""Configuration of the single-floor solver: the energy weights and the sampling settings."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from mansion._io import atomic_write_text
from mansion.exceptions import InvalidInputError
from mansion.models._validation import load_input, validate_input

__all__ = ["EnergyWeights", "SolverSettings"]


class EnergyWeights(BaseModel):
    """Weights of the per-room energy that ranks candidate cuts.

    For a child room r: ``e = ratio·|area−a|/a + seed·z_seed + drift·d/√a
    + corner·max(0, n_int−4) − wall·clamp01(wall_contact) + rect·(1 − area/bbox)
    + aspect·max(0, long/short − 3)``, and the candidate with the lowest Σ e wins. The two shape
    terms (ours, 0 by default so the tuned energy is unchanged) favour compact, rectangular rooms:
    ``bbox`` is the room's bounding box, and the aspect term skips the parent's leftover (a
    corridor may be long). ``d`` is the distance from the room's centroid to its seed; ``z_seed`` is ``d``
    min–max normalised over the candidate's rooms (the paper's term); ``d/√a`` is ``d`` in units
    of the room's own size (ours: the min–max form spans 0..1 in every candidate, so it hardly
    separates candidates).

    The defaults were found by ``mansion tune-weights`` on the T2D development plans with even
    ids (30 random samples of the simplex, then 30 local perturbations of the best; seed 0),
    starting from ratio 6, drift 12, the rest the authors' released values. With the default
    :class:`SolverSettings` of the time (no wall refinement) they score micro-IoU 87.04 /
    macro-IoU 85.86 on the held-out odd ids (all 500 plans: 87.34 / 86.17, no failure; with
    ``refine_walls``, now the default, 90.40 / 89.48 and 90.72 / 89.70), against 80.34 / 77.91 on the even ids for the
    authors' released values (:meth:`paper`), which work on their 1 m grid. Seeds given as centroids are
    worth following closely: drift carries most of the weight. Other weights can be kept in a
    JSON file such as ``{"ratio": 6.0, "seed": 0.2, "drift": 0.0, "wall": 0.8, "corner": 3.0}``
    and read with :meth:`EnergyWeights.load`; keys left out keep their defaults.
    """

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    ratio: float = Field(default=1.28, ge=0.0, description="Relative area error.")
    seed: float = Field(default=0.21, ge=0.0, description="Centroid-to-seed distance (normalised).")
    drift: float = Field(
        default=17.65, ge=0.0, description="Centroid-to-seed distance over √(target area)."
    )
    wall: float = Field(default=0.57, ge=0.0, description="Contact with the parent's envelope.")
    corner: float = Field(default=0.29, ge=0.0, description="Interior corners beyond four.")
    rect: float = Field(
        default=0.0, ge=0.0, description="Share of the room's bounding box it leaves empty."
    )
    aspect: float = Field(
        default=0.0, ge=0.0, description="Bounding-box elongation beyond 3:1 (seeded rooms)."
    )

    @classmethod
    def paper(cls) -> EnergyWeights:
        """The values released by the MANSION authors (ratio 6.0, seed 0.2, wall 0.8, corner 3.0,
        no drift term): area first. The building generator uses them (see
        :func:`mansion.generate_building`)."""
        return cls(ratio=6.0, seed=0.2, drift=0.0, wall=0.8, corner=3.0)

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> EnergyWeights:
        """Read weights from a JSON file; every problem is an :class:`InvalidInputError`."""
        return load_input(cls, path, "energy weights")

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Write the weights as JSON, atomically."""
        return atomic_write_text(path, self.model_dump_json(indent=2) + "\n")

    @classmethod
    def parse(cls, data: EnergyWeights | dict[str, Any]) -> EnergyWeights:
        return validate_input(cls, data, "energy weights")


class SolverSettings(BaseModel):
    """Sampling settings of the cut rounds (adaptive sampling and the Monte Carlo fallback).

    - ``k``: growth of the base seed-perturbation radius with the child's share of the parent
      region, ``R⁰ = r_base + k · a_child / |Ω(parent)|`` (in cells);
    - ``gammas``: the radius multiplier of each retry, ``R_j = γ_j · R⁰`` (non-decreasing; the
      core reuses the last one for retries beyond the list);
    - ``seed_separation``: minimum distance between perturbed seeds, in cells;
    - ``fallback_samples``: candidates drawn by the Monte Carlo fallback when every retry failed;
    - ``min_width``: narrowest allowed room, in cells, for every room of the floor (None: no
      limit); each room's own ``RoomNode.min_width`` (metres) adds to it, the larger rule wins,
      and a rule is capped at the side of the largest square the room's area can hold;
    - ``relax_widths``: a cut round that no candidate passes under its width rules is cut again
      with the rules above ``min_width`` lowered to it, then with every rule lowered to 1.0 m,
      before the solver backtracks (recorded as the round's ``widths_relaxed``); False: the
      round fails as any other;
    - ``max_backtracks``: times per floor a round no candidate passes may send the solver back to
      re-cut the round that made its region (a count, so results stay deterministic);
    - ``strict_backtracks`` (with ``relax_widths``): backtracks spent keeping every width rule
      before a failing round's rules are lowered, the search then going on from where it stands
      (None: lowered at once); see the README's "Room widths" for what these budgets cost;
    - ``refine_walls``: after each cut round, move the walls between the round's rooms one cell at a
      time, from a room better off (relative to its target) towards one worse off, when one of
      the two is off its target on that side, while the energy falls (every move passes the same
      cleanup, width and topology checks as a candidate); False: the paper's cutting node;
    - ``growth``: side choice of the rectangular growth phase: ``"balanced"`` keeps each room
      centred on its seed until a wall or a neighbour stops it (so seeds act as centroids);
      ``"longest"`` grows the longest free side first, as in Lopes et al. (2010);
    - ``reseeds``: in a round whose parent keeps the leftover, times the round may be cut again
      with the seed of a child its winner left short (below 80 % of its target, the parent
      holding half that target beyond its own) moved into the largest piece of that leftover;
      each re-cut draws a tenth of a retry's candidates (at the third retry's radii), and its
      winner is kept when the children's total shortfall falls and their rooms are no more
      elongated or jagged. 0: never, the paper's cutting node (given seeds stay where given).
    - ``slabs``: in a round whose parent keeps the leftover, also lay the round out as the
      corridor typology (``mansion-core``'s ``slab`` module): the parent a straight corridor
      across its region (its width rule or clear width, 1.5–3 m) with rooms on both sides of it
      or, at the region's edge, on one; or, where four bands of rooms fit, two parallel
      corridors joined at one end. The children are split between the bands by their seeds and
      areas and laid side by side along the corridor in the order of their seeds, each at least
      its clear width across; a stub of corridor reaches what the parent must touch outside.
      Each axis gives five single-corridor positions and both two-corridor layouts; they pass
      the same cleanup, width and topology filter as grown candidates, must leave each room a
      1.5 m square and each zone no longer than twice its width, and win when their energy is
      lower. False: the paper's cutting node. Generated floors turn it on.
    - ``wide_retries``: retries each round first spends, at a quarter of a batch each and the
      fifth retry's radii (γ = 2 with the default ``gammas``), with the width rules of its
      rooms raised to their nodes' ``clear_width`` (never beyond the square a room's area
      holds) and the zones it cuts held to the widest clear width of the rooms they will hold;
      a round none of them lays out is cut under its own rules as before. The
      rules a round keeps are capped (``RoomNode.min_width``: 2.0 m, 1.5 m for wider rooms),
      because holding every round to full widths fails many and costs their whole budget.
      0: never (the paper's cutting node); generated floors use 1.
    - ``repair``: once every round is cut, rooms left below their node's ``min_area``,
      ``clear_width`` or ``max_aspect`` take a row or a column at a time from neighbours (one
      neighbour, one straight run of it, the whole face across several, or a neighbour that
      slides over into the room beyond it), or hand a strip narrower than their clear width to
      one. A move is taken when the room's shortfall and the rooms' total fall and no room
      gains a defect (below area or width, elongated, a sliver, no usable square) or more cells
      under its width rule, every donor stays in one piece without a one-cell neck, and every
      realised edge and exterior wall is kept; False: the paper's solver. Generated floors turn
      it on.
    - ``rebalance``: after each round, its rooms below their targets take rows and columns from
      rooms of the round above theirs by the same moves and rules (a child seeded among
      siblings no longer leaves the parent holding its share). Generated floors turn it on.
    - ``rebalance_later_only`` (with ``rebalance``): every round but the first, whose zones stay
      as cut (the first round's rebalance moved a zone's rows from the hub one at a time, a
      sixth of the offline hundred's generation time). Generated floors turn it on.
    - ``keep_first_round`` (with ``repair`` and ``rebalance``): the first round stays as cut and cells move only
      within one of its regions, so the walls between them stay where the cut put them
      (generated floors whose walls the floor above carries as load-bearing walls).
    - ``hold_regions`` (with ``keep_first_round``): the first round's regions, not only its
      rooms, may not straddle a fixed wall (the floors above one whose hub took a narrow
      region's arm, :mod:`mansion.building.regions`).

    How the defaults were chosen (``mansion eval floorplan`` on the T2D development plans, even
    ids, hierarchical mode, micro / macro IoU; and the solver's own benchmark, whose seeds come
    from the offline heuristic planner):

    - ``gammas``: a narrow first retry (0.25), then the paper's sequence without its 3.5. Seeds
      given as centroids gain from a small first radius: with the tuned weights, k = 8 and
      γ = [0.25, 1, 1.25, …] scored 87.65 / 86.48, against 87.52 / 86.30 for k = 4 and
      γ = [0.25, 0.5, 1, 1.5, 2, 3, …] and 87.33 / 86.01 (one failure) for γ₀ = 0.125. Guessed seeds
      need the wider retries: on the 64 × 64 seven-room benchmark with heuristic seeds the
      second retry wins (15 ms per solve), where k = 4 with the slow γ ramp needed six retries
      (30 ms) and the paper's sequence two (10.6 ms).
    - ``k`` = 8, the paper's value (see above; k = 0, 2, 4 were within noise on T2D).
    - ``seed_separation`` = 2 cells: 1 and 2 gave identical T2D scores; 2 keeps seeds apart.
    - ``fallback_samples`` = 400: the fallback never won a round on the 500 T2D plans; 400 costs
      as much as four retries and is kept for harder programs.
    - ``refine_walls`` = True: all 500 plans 90.72 / 89.70 against 87.34 / 86.17 without (odd
      ids 90.40 / 89.48 against 87.04 / 85.86), at the same time; on generated buildings (seeds
      0–41) rooms below 60 % of their target fall from 15.1 % to 13.9 %.
    - ``growth`` = balanced: with the paper's weights and γ from 0.5, balanced growth scored
      78.24 / 76.01 in flat mode against 75.47 / 72.14 for the longest-side rule (first 150 plans).
    """

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    k: float = Field(default=8.0, ge=0.0)
    gammas: list[float] = Field(
        default_factory=lambda: [0.25, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0]
    )
    seed_separation: float = Field(default=2.0, ge=0.0)
    fallback_samples: int = Field(default=400, ge=0)
    min_width: int | None = Field(default=None, ge=1)
    relax_widths: bool = True
    max_backtracks: int = Field(default=8, ge=0)
    strict_backtracks: int | None = Field(default=None, ge=0)
    refine_walls: bool = True
    growth: Literal["balanced", "longest"] = "balanced"
    reseeds: int = Field(default=0, ge=0)
    slabs: bool = False
    wide_retries: int = Field(default=0, ge=0)
    repair: bool = False
    rebalance: bool = False
    rebalance_later_only: bool = False
    keep_first_round: bool = False
    hold_regions: bool = False

    @model_validator(mode="after")
    def _check_gammas(self) -> SolverSettings:
        if not self.gammas:
            raise InvalidInputError("gammas must hold at least one radius multiplier")
        for j, g in enumerate(self.gammas):
            if g <= 0:
                raise InvalidInputError(f"gammas[{j}] = {g:g}; every radius multiplier must be > 0")
            if j and g < self.gammas[j - 1]:
                raise InvalidInputError(
                    f"gammas[{j}] = {g:g} is smaller than gammas[{j - 1}] = "
                    f"{self.gammas[j - 1]:g}; retries widen the search, so gammas must not decrease"
                )
        return self

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> SolverSettings:
        """Read settings from a JSON file; every problem is an :class:`InvalidInputError`."""
        return load_input(cls, path, "solver settings")

    @classmethod
    def parse(cls, data: SolverSettings | dict[str, Any]) -> SolverSettings:
        return validate_input(cls, data, "solver settings")
