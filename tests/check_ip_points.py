#!/usr/bin/env python3
"""The per-IP VTU series (ip.pvd, ip-NNNN.vtu) read by VTK, as ParaView does:
ip.pvd lists one file per row of history.h5; in each, the points are
/ip_position and every point-data array named like a history.h5 dataset
(F, P, sigma and every statistic) equals that dataset's row, every
component (written with 17 digits: exact). Exit code 77 (ctest: skipped)
with a message if VTK's Python module is missing.
Usage: check_ip_points.py OUTPUT_DIR"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

try:
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError:
    print("SKIP: VTK's Python module is missing (Debian: apt-get install python3-vtk9)")
    sys.exit(77)

out = sys.argv[1]
files = [d.get("file") for d in ET.parse(os.path.join(out, "ip.pvd")).getroot().iter("DataSet")]
fails = 0
with h5py.File(os.path.join(out, "history.h5"), "r") as h:
    n_steps, (n_ip, dim) = h["step"].shape[0], h["ip_position"].shape
    if len(files) != n_steps:
        sys.exit(f"FAIL: ip.pvd lists {len(files)} files, history.h5 has {n_steps} rows")
    compared = set()
    for row, name in enumerate(files):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(out, name))
        reader.Update()
        grid = reader.GetOutput()
        points = vtk_to_numpy(grid.GetPoints().GetData())[:, :dim]
        if grid.GetNumberOfPoints() != n_ip or not np.array_equal(points, h["ip_position"][:]):
            print(f"FAIL {name}: points differ from /ip_position")
            fails += 1
        data = grid.GetPointData()
        for k in range(data.GetNumberOfArrays()):
            array = data.GetArrayName(k)
            if array not in h:
                continue
            vtk_values = vtk_to_numpy(data.GetArray(k)).reshape(n_ip, -1)
            h5_values = np.asarray(h[array][row], dtype=float).reshape(n_ip, -1)
            if vtk_values.shape != h5_values.shape or not np.array_equal(vtk_values, h5_values):
                print(f"FAIL {name}: {array} differs from history.h5 row {row}")
                fails += 1
            compared.add(array)
    missing = [d for d in h if d != "ip_position" and h[d].ndim >= 2 and d not in compared]
    if missing:
        print(f"FAIL: history.h5 datasets without a VTU array: {missing}")
        fails += 1
print(f"{len(files)} files, {len(compared)} arrays per file compared with history.h5 "
      f"({', '.join(sorted(compared))}): {'FAIL' if fails else 'ok'}")
sys.exit(1 if fails else 0)
