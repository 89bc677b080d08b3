# -*- encoding=utf-8 -*-
# Glass and steel spheres dropped into a box, Hertz-Mindlin with restitution coefficients per
# material pair.  Written after Yade's examples/DEM2020Benchmark/Case2_rotating_drum_openmp.py
# (materials with labels, en=MatchMaker(matches=...), NewtonIntegrator(damping=0)) and the Yade
# documentation of Ip2_FrictMat_FrictMat_MindlinPhys; the bodies are made with sphere(), wall()
# and geom.facetBox() instead of files.
from yade import utils, geom

r_glass = 1.0e-3        # [m]
r_steel = 1.5 * r_glass
e_gg, e_gs, e_ss, e_gw, e_sw = 0.5, 0.6, 0.7, 0.4, 0.55

glass = O.materials.append(FrictMat(young=63e9, poisson=0.23, density=2500, frictionAngle=radians(20), label='glass'))
steel = O.materials.append(FrictMat(young=210e9, poisson=0.3, density=7800,
                                    frictionAngle=radians(15), label='steel'))
wallMat = O.materials.append(FrictMat(young=70e9, poisson=0.25, density=2700, label='box'))

for i in range(3):
	O.bodies.append(sphere((0, 0, 0.01 * (i + 1)), r_glass, material=glass))
O.bodies.append(utils.sphere((0.005, 0, 0.01), radius=r_steel, material='steel'))
O.bodies.append(utils.wall(0, axis=2, material=wallMat))
O.bodies.append(geom.facetBox((0, 0, 0.05), (0.02, 0.02, 0.05), wallMask=31, material='box'))

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop(
                [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                [Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=((glass, glass, e_gg), (glass, steel, e_gs),
                                                                         (steel, steel, e_ss), (glass, wallMat, e_gw),
                                                                         (steel, wallMat, e_sw))))],
                [Law2_ScGeom_MindlinPhys_Mindlin()]
        ),
        NewtonIntegrator(damping=0, gravity=(0, 0, -9.81)),
]
O.dt = 0.5 * PWaveTimeStep()
O.run(100000, True)
