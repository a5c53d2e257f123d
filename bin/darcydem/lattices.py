"""Grain lattices the coupled tests build their closed-box cases from."""


def expanding_lattice(rate, zc, radius=0.004, spacing=0.01):
    """Rows 'x y z r vx vy vz' of a 4 x 4 x 12 lattice (spacing [m], first
    layer at z = 0.065 m) filling tests/cases/closedBox, each grain moving
    with v_z = rate (z - zc): an affine expansion (rate > 0) or compaction
    about the height zc, uniform inside the lattice."""
    rows = []
    for k in range(12):
        z = 0.065 + k * spacing
        for j in range(4):
            for i in range(4):
                rows.append((0.005 + i * spacing, 0.005 + j * spacing, z, radius,
                             0.0, 0.0, rate * (z - zc)))
    return rows
