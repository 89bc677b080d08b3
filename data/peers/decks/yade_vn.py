# Velocity-dependent restitution (Yade 2024.02a and later: en with vn, the viscoelastic damping
# of Brilliantov et al. 1996 with the Mueller and Poeschel 2011 Pade), the law's parameters set
# through its label as Yade's example Damping_HM.py (examples, directory test) does.
young = 1e9
O.materials.append(FrictMat(young=young, poisson=0.3, density=1500))
O.bodies.append(sphere((0, 0, 0), 0.002))
O.bodies.append(sphere((0.0041, 0, 0), 0.002))
O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys(label='ip2')],
                        [Law2_ScGeom_MindlinPhys_Mindlin()]),
        NewtonIntegrator(damping=0.0),
]
ip2.en = 0.8
ip2.vn = 2.0
O.dt = 2e-7
