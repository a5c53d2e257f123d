"""bin/makeGrains writes random packings of spheres and capsules (issue
10): sizes and aspect ratios from ranges, orientations uniform over
rotations, spheres and capsules mixed by a fraction, no two grains
touching, the same file for the same seed. Checked on the written files,
independently of makeGrains' own geometry."""

import os
import subprocess

import numpy as np

MAKE_GRAINS = os.path.join(os.path.dirname(__file__), "..", "..", "bin", "makeGrains")
RUN = os.path.join(os.path.dirname(__file__), "..", "run", "make_grains")


def make(name, *args):
    os.makedirs(RUN, exist_ok=True)
    path = os.path.join(RUN, name)
    subprocess.run([MAKE_GRAINS, *map(str, args), "-o", path], check=True,
                   stdout=subprocess.DEVNULL)
    return path


def read(path):
    """(x (n, 3), r, h, q (n, 4)) of a grains file; spheres get h = 0, q = 1."""
    rows = [l.split() for l in open(path) if l.strip() and not l.startswith("#")]
    assert all(len(v) in (4, 9) for v in rows), "a line is neither sphere nor capsule"
    x = np.array([[float(c) for c in v[:3]] for v in rows])
    r = np.array([float(v[3]) for v in rows])
    h = np.array([float(v[4]) if len(v) == 9 else 0.0 for v in rows])
    q = np.array([[float(c) for c in v[5:9]] if len(v) == 9 else [1, 0, 0, 0] for v in rows])
    return x, r, h, q


def axes(q):
    w, x, y, z = q.T
    return np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=1)


def test_random_capsule_packing_has_no_contact():
    """300 grains, half capsules of aspect 1.5-3, in a periodic box. The
    distance of two core segments is measured by sampling both at 51
    points: the sampled minimum exceeds the true one by at most
    (delta/2)(|a_i| + |a_j|), delta = 0.04 the parameter spacing, so
    sampled - that bound > r_i + r_j proves the grains apart (pairs whose
    bounding spheres, radius r + h, do not touch are apart anyway)."""
    box = np.array([0.1, 0.1])
    path = make("random.txt", "--box", *box, "--z", 0, 0.3, "--radius", 0.004, 0.005,
                "--layout", "random", "--count", 300, "--capsule-fraction", 0.5,
                "--aspect", 1.5, 3, "--seed", 4)
    x, r, h, q = read(path)
    a = axes(q) * h[:, None]
    u = np.linspace(-1, 1, 51)
    samples = x[:, None, :] + u[None, :, None] * a[:, None, :]   # (n, 51, 3)
    bounding = r + h
    worst, pairs = np.inf, 0
    for i in range(len(r)):
        c = x - x[i]
        c[:, :2] -= box * np.round(c[:, :2] / box)
        near = np.flatnonzero(np.linalg.norm(c, axis=1) < bounding + bounding[i])
        near = near[near > i]
        if len(near) == 0:
            continue
        pairs += len(near)
        d = samples[near, :, None, :] - samples[i][None, None, :, :]
        d[..., :2] -= box * np.round(d[..., :2] / box)
        sampled = np.sqrt(np.min(np.einsum("...k,...k->...", d, d), axis=(1, 2)))
        lower = sampled - 0.02 * (np.linalg.norm(a[i]) + np.linalg.norm(a[near], axis=1))
        worst = min(worst, np.min(lower / (r[i] + r[near])))
    # z: every capsule inside [0, 0.3] with its caps
    reach = r + np.abs(a[:, 2])
    print(f"{len(r)} grains, {np.count_nonzero(h)} capsules, {pairs} pairs within"
          f" bounding reach; smallest surface distance"
          f" bound / (r_i + r_j) = {worst:.3f} (makeGrains keeps 1 + gap = 1.1)")
    assert worst > 1.0
    assert np.all(x[:, 2] - reach >= 0) and np.all(x[:, 2] + reach <= 0.3)


def test_shapes_orientations_and_fraction():
    """A lattice of about 2900 grains, capsule fraction 0.3, aspect 1.5-3.
    The capsule share is binomial (4 standard deviations allowed, a false
    alarm once in 16000 runs); the axes uniform on the sphere: each
    component's mean 0 with standard deviation 1/sqrt(3 n) and the mean of
    a_z^2 equal to 1/3 with standard deviation sqrt(4/45 / n) (E z^4 = 1/5),
    again 4 deviations; quaternions of unit length to the 10 digits written."""
    path = make("lattice.txt", "--box", 0.3, 0.3, "--z", 0, 0.3, "--radius", 0.002, 0.003,
                "--capsule-fraction", 0.3, "--aspect", 1.5, 3, "--seed", 11)
    x, r, h, q = read(path)
    n, capsule = len(r), h > 0
    share = np.count_nonzero(capsule) / n
    sigma = np.sqrt(0.3 * 0.7 / n)
    print(f"{n} grains, capsule share {share:.4f} (expected 0.3 +- {sigma:.4f})")
    assert abs(share - 0.3) < 4 * sigma
    aspect = 1 + h[capsule] / r[capsule]
    print(f"aspect ratios {aspect.min():.4f} .. {aspect.max():.4f}")
    assert aspect.min() >= 1.5 - 1e-8 and aspect.max() <= 3 + 1e-8
    assert aspect.min() < 1.55 and aspect.max() > 2.95   # the whole range is used
    assert np.all(np.abs(np.linalg.norm(q[capsule], axis=1) - 1) < 1e-9)
    e = axes(q[capsule])
    m = len(e)
    means, z2 = e.mean(axis=0), np.mean(e[:, 2]**2)
    print(f"axis component means {means} (sd {1 / np.sqrt(3 * m):.4f}),"
          f" mean a_z^2 {z2:.4f} (1/3, sd {np.sqrt(4 / 45 / m):.4f})")
    assert np.all(np.abs(means) < 4 / np.sqrt(3 * m))
    assert abs(z2 - 1 / 3) < 4 * np.sqrt(4 / 45 / m)


def test_same_seed_same_file():
    args = ["--box", 0.1, 0.1, "--z", 0, 0.2, "--radius", 0.004, 0.005, "--layout", "random",
            "--count", 100, "--capsule-fraction", 0.5, "--aspect", 2]
    first = open(make("seed_a.txt", *args, "--seed", 3)).read()
    again = open(make("seed_b.txt", *args, "--seed", 3)).read()
    other = open(make("seed_c.txt", *args, "--seed", 5)).read()
    assert first == again and first != other


def test_walls_on_x_and_strain_rate_velocities():
    """--periodic y: 200 capsules between walls at x = 0 and LX keep their
    caps inside ([0, LX] along x with r + h |a_x|, exactly as along z), and
    no two touch (x not wrapped: the plain distance of the core segments,
    sampled as in the test above). --strain-rate: every grain's velocity is
    E_ii (x_i - o_i) to the 10 significant digits written: within
    5e-10 (|v_i| + |E_ii| |x_i|), the rounding of both numbers."""
    lx, ly, lz = 0.012, 0.016, 0.012
    rate, origin = np.array([-1.0, 0.0, -0.5]), np.array([0.006, 0.0, 0.003])
    path = make("walls_x.txt", "--box", lx, ly, "--z", 0, lz, "--radius", 4e-4, 6e-4,
                "--layout", "random", "--count", 200, "--capsule-fraction", 1,
                "--aspect", 2, 4, "--periodic", "y", "--strain-rate", *rate,
                "--strain-origin", *origin, "--seed", 3)
    rows = np.array([[float(c) for c in l.split()] for l in open(path)
                     if l.strip() and not l.startswith("#")])
    assert rows.shape[1] == 12
    x, r, h, q, v = rows[:, :3], rows[:, 3], rows[:, 4], rows[:, 5:9], rows[:, 9:12]
    a = axes(q) * h[:, None]
    reach = r[:, None] + np.abs(a)
    inside_x = np.min(np.minimum(x[:, 0] - reach[:, 0], lx - x[:, 0] - reach[:, 0]))
    inside_z = np.min(np.minimum(x[:, 2] - reach[:, 2], lz - x[:, 2] - reach[:, 2]))
    u = np.linspace(-1, 1, 51)
    samples = x[:, None, :] + u[None, :, None] * a[:, None, :]
    worst = np.inf
    for i in range(len(r)):
        d = samples[i + 1:, :, None, :] - samples[i][None, None, :, :]
        d[..., 1] -= ly * np.round(d[..., 1] / ly)
        sampled = np.sqrt(np.min(np.einsum("...k,...k->...", d, d), axis=(1, 2)))
        lower = sampled - 0.02 * (np.linalg.norm(a[i]) + np.linalg.norm(a[i + 1:], axis=1))
        if len(lower):
            worst = min(worst, np.min(lower / (r[i] + r[i + 1:])))
    bound = 5e-10 * (np.abs(v) + np.abs(rate) * np.abs(x)) + 1e-15
    error = np.max(np.abs(v - rate * (x - origin)) / bound)
    print(f"clearance to the x walls {inside_x:.2e} m, to the z walls {inside_z:.2e} m;"
          f" smallest surface distance bound / (r_i + r_j) = {worst:.3f};"
          f" velocity error {error:.2f} of its rounding bound")
    assert inside_x >= 0 and inside_z >= 0
    assert worst > 1.0
    assert error <= 1.0
