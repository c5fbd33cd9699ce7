"""GeoClaw's set-up of bench/geoclaw/compare.sh: writes setrun.py, the flat bed and the hump
into a run folder. Usage: python setrun_hump.py RUN_DIR N T

From GeoClaw's example tsunami/bowl-radial (clawpack 5.14.0), changed to: one AMR level
(a uniform N × N grid), a flat bed at -10 m over [-100, 100]^2 m, a square hump of +1 m over
[-10, 10]^2 m (qinit type 4: a surface perturbation), walls, Manning n = 0.025, output only at
the start and the end, no gauges, no checkpoints.
"""

import os
import sys

import numpy as np

run, n, t = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
os.makedirs(run, exist_ok=True)

# Bed: a flat plane, two nodes beyond the domain each way (topotype 2: a header, values).
with open(os.path.join(run, "flat.tt2"), "w") as f:
    f.write("3 ncols\n3 nrows\n-110.0 xll\n-110.0 yll\n110.0 cellsize\n-9999 nodata_value\n")
    for _ in range(3):
        f.write("-10.0\n-10.0\n-10.0\n")

# Hump: +1 m inside [-10, 10]^2, on a fine xyz grid (topotype 1) so that its edge falls between
# cell centres as riprap's box region does.
h = 200.0 / n
xs = np.arange(-100.0, 100.0 + 0.5 * h, h / 2)
with open(os.path.join(run, "hump.xyz"), "w") as f:
    for y in xs[::-1]:
        for x in xs:
            f.write("%.6f %.6f %.1f\n" % (x, y, 1.0 if abs(x) < 10 and abs(y) < 10 else 0.0))

setrun = f'''
import os
import numpy as np
from clawpack.clawutil import data


def setrun(claw_pkg="geoclaw"):
    rundata = data.ClawRunData(claw_pkg, 2)
    c = rundata.clawdata
    c.num_dim = 2
    c.lower = [-100.0, -100.0]
    c.upper = [100.0, 100.0]
    c.num_cells = [{n}, {n}]
    c.num_eqn = 3
    c.num_aux = 1
    c.capa_index = 0
    c.t0 = 0.0
    c.restart = False
    c.output_style = 1
    c.num_output_times = 1
    c.tfinal = {t}
    c.output_t0 = False
    c.output_format = "binary"
    c.output_q_components = "all"
    c.output_aux_components = "none"
    c.output_aux_onlyonce = True
    c.verbosity = 1
    c.dt_variable = True
    c.dt_initial = 1e-3
    c.dt_max = 1e99
    c.cfl_desired = 0.9
    c.cfl_max = 1.0
    c.steps_max = 1000000
    c.order = 2
    c.dimensional_split = "unsplit"
    c.transverse_waves = 2
    c.num_waves = 3
    c.limiter = ["mc", "mc", "mc"]
    c.use_fwaves = True
    c.source_split = "godunov"
    c.num_ghost = 2
    c.bc_lower = ["wall", "wall"]
    c.bc_upper = ["wall", "wall"]
    c.checkpt_style = 0
    a = rundata.amrdata
    a.amr_levels_max = 1
    a.refinement_ratios_x = [2]
    a.refinement_ratios_y = [2]
    a.refinement_ratios_t = [2]
    a.aux_type = ["center"]
    a.flag_richardson = False
    a.flag2refine = True
    a.regrid_interval = 1000000
    a.regrid_buffer_width = 2
    a.clustering_cutoff = 0.7
    a.verbosity_regrid = 0
    g = rundata.geo_data
    g.gravity = 9.81
    g.coordinate_system = 1
    g.earth_radius = 6367.5e3
    g.coriolis_forcing = False
    g.sea_level = 0.0
    g.dry_tolerance = 1.0e-6
    g.friction_forcing = True
    g.manning_coefficient = 0.025
    g.friction_depth = 1.0e6
    rundata.refinement_data.wave_tolerance = 1.0e10
    rundata.refinement_data.variable_dt_refinement_ratios = False
    rundata.topo_data.topofiles.append([2, "flat.tt2"])
    rundata.qinit_data.qinit_type = 4
    rundata.qinit_data.qinitfiles = [["hump.xyz"]]
    return rundata


if __name__ == "__main__":
    setrun().write()
'''
with open(os.path.join(run, "setrun.py"), "w") as f:
    f.write(setrun)
