# Cundall's numerical damping left at NewtonIntegrator's default (0.2), a linear ViscElMat
# material, and spheres whose radius is a loop variable: what the checker reports and skips.
# After Yade's example mindlin.py (examples, directory test) and the ViscElMat documentation.
import random
mat = O.materials.append(FrictMat(young=1e8, poisson=0.25, density=2000, label='sand'))
visc = O.materials.append(ViscElMat(young=1e8, poisson=0.25, density=2000, en=0.5, et=0.5, label='visc'))
O.bodies.append(sphere((0, 0, 0), 0.005, material=mat))
O.bodies.append(sphere((0, 0, 0.02), 0.005, material=visc))
for i in range(10):
	r = random.uniform(0.004, 0.006)
	O.bodies.append(sphere((0.02 * i, 0, 0.05), r, material=mat))
O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys(betan=0.3)],
                        [Law2_ScGeom_MindlinPhys_Mindlin()]),
        NewtonIntegrator(gravity=(0, 0, -9.81)),
]
O.dt = 1e-6
