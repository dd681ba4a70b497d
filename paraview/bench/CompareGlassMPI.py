"""pvpython CompareGlassMPI.py OUTPUT_DIR: adds psnr_one_rank to BenchGlassMPI.py's rows.csv
(each row's last picture against the one-rank run's picture of the same method), written as
OUTPUT_DIR/mpi.csv."""
import csv
import os
import sys

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
from glass_images import read_png  # noqa: E402

output = sys.argv[1]
with open(os.path.join(output, "rows.csv")) as handle:
    rows = list(csv.DictReader(handle))
for row in rows:
    one = read_png(os.path.join(output, "ranks1_%s.png" % row["method"]))
    many = read_png(os.path.join(output, "ranks%s_%s.png" % (row["ranks"], row["method"])))
    mse = numpy.mean((one - many) ** 2.0)
    row["psnr_one_rank"] = "100.0" if mse == 0 else "%.1f" % (10.0 * numpy.log10(255.0 ** 2 / mse))
with open(os.path.join(output, "mpi.csv"), "w", newline="") as handle:
    writer = csv.DictWriter(handle, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)
for row in rows:
    print(" ".join("%s=%s" % item for item in row.items()))
