#!/usr/bin/env python3
"""pandas reads every command's CSV with no options and gets the types right.

    /usr/bin/python3 .ci/check_pandas.py [build/ogive]

For each command (thrust, profile, check, curve, bench, with their default columns and with
--all-columns): pandas.read_csv with no arguments; every numeric column is a number type, every boolean
column bool, no column holds 'nan' or 'inf' text, and a filter on an echoed input (rise_ratio == 0.2,
eccentricity == 0.3, support_displacement_ratio == 5e-05) finds its rows. Exit 0 if all hold, 1 with a
line per failure otherwise, 2 if pandas is missing (Debian: apt-get install python3-pandas).
"""
import io
import subprocess
import sys

try:
    import pandas as pd
    from pandas.api import types
except ImportError:
    sys.stderr.write("check_pandas.py: needs pandas (Debian: apt-get install -y python3-pandas; run /usr/bin/python3)\n")
    sys.exit(2)

OGIVE = sys.argv[1] if len(sys.argv) > 1 else "build/ogive"
BOOLEAN = {"plane_strain", "crown_hinge", "cracked", "thrust_in_kern", "thrust_in_section", "within_tolerance"}
TEXT = {"curve", "method", "integrator", "status", "message", "warning", "reference_method", "reference_status",
        "chosen_method", "file", "joints", "weight", "hinges_min", "hinges_max", "hinges_collapse", "hinges_horizontal", "state", "hinge",
        "left_support", "right_support", "domain", "loads_file", "section", "beam_model", "verdict", "governing",
        "geometric_safety_factor_outcome", "load_factor_outcome", "horizontal_load_factor_outcome",
        "spread_capacity_ratio_outcome", "max_thrust_eccentricity_outcome", "limit_status", "warnings"}

RUNS = [
    (["thrust", "--eccentricity", "0:1:11"], ("eccentricity", 0.3, 1)),
    (["thrust", "--curve", "segmental", "--rise-ratio", "0.1,0.2,0.3"], ("rise_ratio", 0.2, 1)),
    (["thrust", "--point-load", "1e4", "--point-load-at", "0:1:11", "--supports", "pinned"], ("point_load_at", 0.5, 1)),
    (["thrust", "--loads-file", "data/loads/quarter-point-and-half-live.csv", "--left-settlement-ratio", "0,1e-4"],
     ("left_settlement_ratio", 1e-4, 1)),
    (["thrust", "--support-displacement-ratio", "0:0.0003:7"], ("support_displacement_ratio", 5e-05, 1)),
    (["thrust", "--curve", "catenary", "--rise-ratio", "0.5,2", "--thickness-ratio", "0.5"], None),
    (["profile", "--eccentricity", "0,0.5", "--stations", "11"], ("eccentricity", 0.5, 11)),
    (["profile", "--method", "shooting", "--max-steps", "3"], None),
    (["profile", "--section", "no-tension", "--support-displacement-ratio", "0,1e-4", "--stations", "9"],
     ("support_displacement_ratio", 1e-4, 9)),
    (["check", "--curve", "parabolic", "--rise-ratio", "0.2,0.4"], ("rise_ratio", 0.2, 3)),  # quadrature, shooting, multiple shooting
    (["curve", "--curve", "elliptical", "--rise-ratio", "0.2:0.4:3", "--stations", "5"], ("rise_ratio", 0.3, 5)),
    (["bench", "--eccentricity", "0.5", "--method", "closed-form,shooting", "--rtol", "1e-6,1e-8", "--repeats", "1"], None),
    (["limit", "--eccentricity", "0:1:5", "--thickness-ratio", "0.15"], ("eccentricity", 0.25, 1)),
    (["assess", "--eccentricity", "0:1:5", "--thickness-ratio", "0.15", "--point-load", "1e5", "--require-thrust",
      "section"], ("eccentricity", 0.25, 1)),
    (["limit", "--point-load", "2e5", "--thrust-line", "collapse"], None),
]


def main():
    failures = []
    for args, probe in RUNS:
        for extra in ([], ["--all-columns"]):
            cmd = [OGIVE] + args + extra
            res = subprocess.run(cmd, capture_output=True, text=True)
            where = " ".join(cmd[1:])
            if res.returncode not in (0, 3):
                failures.append(f"{where}: exit {res.returncode}: {res.stderr.strip()}")
                continue
            if "nan" in res.stdout.replace("message", "") or "inf" in res.stdout.replace("info", ""):
                for line in res.stdout.splitlines():
                    if any(tok in ("nan", "inf", "-inf") for tok in line.split(",")):
                        failures.append(f"{where}: a nan or inf field: {line[:120]}")
            df = pd.read_csv(io.StringIO(res.stdout))
            for col in df.columns:
                series = df[col]
                if series.isna().all():
                    continue  # an empty column (no number, or no message) has no type to check
                if col in BOOLEAN:
                    # With an empty field (no answer: an impossible scene) pandas keeps True/False as
                    # objects beside NaN; without, the column is bool.
                    present = series.dropna()
                    if not (types.is_bool_dtype(series) or all(isinstance(v, bool) for v in present)):
                        failures.append(f"{where}: {col} is {series.dtype}, not bool")
                elif col in TEXT:
                    if not types.is_object_dtype(series):
                        failures.append(f"{where}: {col} is {series.dtype}, not text")
                elif not types.is_numeric_dtype(series):
                    failures.append(f"{where}: {col} is {series.dtype}, not a number")
            if probe and (extra or probe[0] in df.columns):
                name, value, count = probe
                found = len(df[df[name] == value])
                if found != count:
                    failures.append(f"{where}: df[df.{name} == {value}] found {found} rows, not {count}")
    for f in failures:
        print(f"check_pandas.py: {f}")
    print(f"check_pandas.py: {len(RUNS) * 2} runs read by pandas {pd.__version__}, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
