"""How the gmsh meshes beside this script were made (gmsh 4.15.2 from PyPI; run it with that gmsh installed).

- ``barge.msh``: a 40 x 10 m box barge, draft 3 m, freeboard 1 m (the body frame: x forward, z up, the
  waterline at z = 0), its whole closed surface in triangles of about 2.5 m, in a physical group "hull", MSH 4.1.
- ``spar_v22.msh``: a spar of radius 5 m, draft 30 m, 5 m above the water, quadrangles where gmsh could recombine
  them and triangles elsewhere, no physical group (every element saved), MSH 2.2, the older format many
  meshers still write.
"""

import gmsh

gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)

gmsh.model.add("barge")
box = gmsh.model.occ.addBox(-20.0, -5.0, -3.0, 40.0, 10.0, 4.0)
gmsh.model.occ.synchronize()
surfaces = [tag for _, tag in gmsh.model.getBoundary([(3, box)], oriented=False)]
gmsh.model.addPhysicalGroup(2, surfaces, name="hull")
gmsh.option.setNumber("Mesh.MeshSizeMax", 2.5)
gmsh.model.mesh.generate(2)
gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
gmsh.write("barge.msh")

gmsh.model.add("spar")
gmsh.model.occ.addCylinder(0.0, 0.0, -30.0, 0.0, 0.0, 35.0, 5.0)
gmsh.model.occ.synchronize()
gmsh.option.setNumber("Mesh.MeshSizeMax", 2.0)
gmsh.option.setNumber("Mesh.RecombineAll", 1)
gmsh.option.setNumber("Mesh.SaveAll", 1)
gmsh.model.mesh.generate(2)
gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
gmsh.write("spar_v22.msh")
gmsh.finalize()
