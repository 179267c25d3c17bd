"""ellc_fea: open finite-element reference for the Becker-Kamlah ellipsoid contact law.

Pipeline (one module per job):
  case      -- read and validate a case TOML (same tables as `ellc curve`)
  mesh      -- gmsh: two ellipsoid octants touching at the origin, graded mesh
  deck      -- write the CalculiX input deck
  runner    -- run ccx, detect convergence failure
  datfile   -- parse the .dat output (driven displacement, reaction force, contact stress)
  curve     -- turn parsed output into overlap/force rows and write the CSV
Units: micrometre, MPa, micronewton.
"""
