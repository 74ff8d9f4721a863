"""Reading an RVE packing (PREFIX.rve.data + PREFIX.vars, build_frame.py or
build_frame_3d.py layout) and writing altered copies of it, for the scripts
that make broken packings for the bad-input tests."""
import os


class RveData:
    """The atoms of PREFIX.rve.data (rows of strings) and its vars file."""

    def __init__(self, prefix):
        self.lines = open(prefix + ".rve.data").read().splitlines()
        self.vars_text = open(prefix + ".vars").read()
        self.first = next(i for i, l in enumerate(self.lines) if l.startswith("Atoms")) + 2
        self.atoms = [l.split() for l in self.lines[self.first:] if l.strip()]

    def cell_side(self, axis):
        """rve_Lx, rve_Ly or rve_Lz of the vars file (axis 'x', 'y' or 'z')."""
        return float(next(l for l in self.vars_text.splitlines() if f"rve_L{axis} " in l).split()[-1])

    def write(self, out, name, rows):
        """OUT/NAME.rve.data with @p rows as its atoms, and an unchanged OUT/NAME.vars."""
        os.makedirs(out, exist_ok=True)
        head = [l if not l.endswith(" atoms") else f"{len(rows)} atoms" for l in self.lines[:self.first]]
        with open(f"{out}/{name}.rve.data", "w") as f:
            f.write("\n".join(head + [" ".join(r) for r in rows]) + "\n")
        with open(f"{out}/{name}.vars", "w") as f:
            f.write(self.vars_text)
