"""A hull built with `hullopt hull`, read back for the diagnostic scripts: its draught and the stations of its
first body (offsets.csv; docs/file-formats.md)."""
import collections
import csv
import json
import os
import subprocess


def first_body_stations(hullopt, config, work):
    """Builds the hull of `config` into work/hull. Returns (draught T [m], stations), stations an ordered
    {x_m: [(y_m, z_m), ...]} of the first body, points and stations in file order."""
    out = os.path.join(work, "hull")
    subprocess.run([hullopt, "hull", config, "--out", out], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "hydrostatics.json")) as f:
        T = json.load(f)["T_m"]
    stations = collections.OrderedDict()
    first_body = None
    with open(os.path.join(out, "offsets.csv")) as f:
        for r in csv.DictReader(row for row in f if not row.startswith("#")):
            body = r.get("body", "")
            if first_body is None:
                first_body = body
            if body == first_body:
                stations.setdefault(float(r["x_m"]), []).append((float(r["y_m"]), float(r["z_m"])))
    return T, stations
