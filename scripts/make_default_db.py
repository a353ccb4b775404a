"""Write the default database's flat files, datasets/db/*.db: SYNTHETIC people.

Nobody in these files exists.  Each person is drawn, with a fixed seed, from
the population statistics shipped in datasets/ (global.dat, girth.dat,
jntlmt.dat, cmass.dat) by the two-piece normal model of
sass_tui/model/population/percentile.py; a shared body-size factor makes stature, mass
and the dimensions of one person go together.  Strengths come from assumed
medians (STRENGTH_MEDIAN_NM below, rough magnitudes, no data set behind them)
scaled by body mass.  Every person's `source` field says so, and
docs/data-sources.md, "Database", describes the method.

Run from the repository root:  python scripts/make_default_db.py
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from sass_tui.db.engine.schema import (
    ELBOW_MOTIONS,
    SHOULDER_MOTIONS,
    WRIST_MOTIONS,
    PeopleBatch,
    girth_mass_fractions,
)
from sass_tui.db.people.flatfile import write_flat_files
from sass_tui.model import datasets
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, JOINT_LIMITS
from sass_tui.model.population.percentile_arrays import value_at
from sass_tui.model.strength.strength import ISOKINETIC_DECAY_PER_DEG_S

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "datasets" / "db"
SEED = 1988
PEOPLE_PER_GENDER = 100
SOURCE = (
    "SYNTHETIC (not a real person): drawn by scripts/make_default_db.py, seed 1988, "
    "from the datasets/*.dat population statistics"
)
# Assumed isometric medians of a 50th-percentile man, N-m; women 0.6 of these.
STRENGTH_MEDIAN_NM = {
    "shoulder_abduction": 55.0,
    "shoulder_adduction": 70.0,
    "shoulder_flexion": 60.0,
    "shoulder_extension": 75.0,
    "shoulder_medial_rotation": 45.0,
    "shoulder_lateral_rotation": 35.0,
    "elbow_flexion": 65.0,
    "elbow_extension": 45.0,
    "forearm_pronation": 8.0,
    "forearm_supination": 10.0,
    "wrist_flexion": 12.0,
    "wrist_extension": 8.0,
    "wrist_radial_deviation": 11.0,
    "wrist_ulnar_deviation": 10.0,
}
FEMALE_STRENGTH_FACTOR = 0.6
STRENGTH_SPREAD = 0.25  # log-normal sigma


def _percentiles(z: np.ndarray) -> np.ndarray:
    cdf = 0.5 * (1.0 + np.vectorize(math.erf)(z / math.sqrt(2.0)))
    return np.clip(cdf * 100.0, 0.5, 99.5)


def generate(rng: np.random.Generator) -> PeopleBatch:
    stats = {
        g: read_population_file(datasets.path(datasets.FILES[g]), g)
        for g in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS)
    }
    global_stats = read_population_file(datasets.path("global.dat"), GLOBAL)
    parts = []
    next_id = 1
    for gender in ("male", "female"):
        n = PEOPLE_PER_GENDER
        size = rng.standard_normal(n)
        glob = global_stats.stats(gender)[:, 0, :]  # (stature, mass) x (5, 50, 95)
        stature = value_at(glob[0], _percentiles(size))
        mass_z = 0.6 * size + 0.8 * rng.standard_normal(n)
        mass = value_at(glob[1], _percentiles(mass_z))

        def group(g: str) -> np.ndarray:
            s = stats[g].stats(gender)  # (rows, 3, 3)
            z = 0.6 * size[:, None, None] + 0.8 * rng.standard_normal((n,) + s.shape[:2])
            return value_at(s, _percentiles(z))

        girth = np.empty((n, 25, 4))
        girth[:, :, :3] = group(GIRTH)
        girth[:, :, 3] = mass[:, None] * girth_mass_fractions()[None, :]
        hand = rng.choice(["right", "left", "either"], size=n, p=[0.88, 0.10, 0.02])
        ids = np.arange(next_id, next_id + n)
        letter = gender[0].upper()
        batch = PeopleBatch(
            id_num=ids,
            name=[f"SYNTH_{letter}_{k + 1:03d}" for k in range(n)],
            gender=[gender] * n,
            stature=np.round(stature, 1),
            mass=np.round(mass, 1),
            handedness=hand.tolist(),
            age=rng.integers(19, 46, n).astype(float),
            source=[SOURCE] * n,
            source_key=[None] * n,
            girth=np.round(girth, 2),
            joint_limits=np.round(group(JOINT_LIMITS), 2),
            center_of_mass=np.round(group(CENTER_OF_MASS), 2),
        )
        _strength(batch, rng, mass / global_stats.stats(gender)[1, 0, 1], gender)
        parts.append(batch)
        next_id += n
    return _concat(parts)


def _strength(
    batch: PeopleBatch, rng: np.random.Generator, mass_ratio: np.ndarray, gender: str
) -> None:
    factor = FEMALE_STRENGTH_FACTOR if gender == "female" else 1.0
    for i in range(len(batch)):
        person = (
            factor * mass_ratio[i] ** (2 / 3) * math.exp(STRENGTH_SPREAD * rng.standard_normal())
        )
        experiments = [(1, "right", "isometric", 0.0)]
        if i % 3 == 0:
            experiments.append((2, "right", "isokinetic", 60.0))
        for exp, side, kind, speed in experiments:
            slow = math.exp(-ISOKINETIC_DECAY_PER_DEG_S * speed)

            def value(motion: str) -> float:
                noise = math.exp(0.1 * rng.standard_normal())
                return round(STRENGTH_MEDIAN_NM[motion] * person * slow * noise, 2)

            batch.strength_par.append((i, exp, side, kind, speed, 0.0, 0.0))
            for axis, (pos, neg) in SHOULDER_MOTIONS.items():
                batch.shoulder.append((i, exp, 30.0, 45.0, 0.0, 90.0, axis, value(pos), value(neg)))
            batch.elbow.append(
                (
                    i,
                    exp,
                    90.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    0.0,
                    value(ELBOW_MOTIONS[0]),
                    value(ELBOW_MOTIONS[1]),
                )
            )
            for axis, (pos, neg) in WRIST_MOTIONS.items():
                batch.wrist.append((i, exp, 0.0, 0.0, 0.0, 90.0, axis, value(pos), value(neg)))


def _concat(parts: list[PeopleBatch]) -> PeopleBatch:
    out = PeopleBatch(
        id_num=np.concatenate([p.id_num for p in parts]),
        name=sum((p.name for p in parts), []),
        gender=sum((p.gender for p in parts), []),
        stature=np.concatenate([p.stature for p in parts]),
        mass=np.concatenate([p.mass for p in parts]),
        handedness=sum((p.handedness for p in parts), []),
        age=np.concatenate([p.age for p in parts]),
        source=sum((p.source for p in parts), []),
        source_key=sum((p.source_key for p in parts), []),
        girth=np.concatenate([p.girth for p in parts]),
        joint_limits=np.concatenate([p.joint_limits for p in parts]),
        center_of_mass=np.concatenate([p.center_of_mass for p in parts]),
    )
    offset = 0
    for p in parts:
        for key in ("strength_par", "shoulder", "elbow", "wrist"):
            getattr(out, key).extend((i + offset, *rest) for i, *rest in getattr(p, key))
        offset += len(p)
    return out


def main() -> None:
    batch = generate(np.random.default_rng(SEED))
    for path in write_flat_files(batch, OUT):
        sys.stdout.write(f"wrote {path.relative_to(ROOT)}\n")


if __name__ == "__main__":
    main()
