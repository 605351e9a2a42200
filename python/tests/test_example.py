"""The example in examples/ runs, plots and interpolates as its text says."""
import os
import pathlib
import re
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "interpolate_2d.py"


def test_interpolation_example(tmp_path):
    output = tmp_path / "picture.png"
    done = subprocess.run([sys.executable, str(EXAMPLE), str(output)], capture_output=True, text=True,
                          timeout=120, env=dict(os.environ, MPLBACKEND="Agg"))
    assert done.returncode == 0, done.stderr
    assert output.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and output.stat().st_size > 50000
    assert "cover 1.000000 of the unit square" in done.stdout
    mean_error = float(re.search(r"mean ([0-9.]+)", done.stdout).group(1))
    assert mean_error < 0.01  # a linear interpolant of a smooth function on 400 samples
