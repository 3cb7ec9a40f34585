r"""
Tutorial: qualitative analysis, Examples 3 and 4 and textbook results

This module only holds documentation: worked sessions of the analysis part
(the qualitative analysis of :doc:`the method </method>`), doctested.

Example 3: invariant manifolds of the spherical pendulum
========================================================

The spherical pendulum of Example 1, its Routh function for the cyclic
angle `\psi` (equation (10))::

    sage: from sage_dynsym import load
    sage: from sage_dynsym.analysis import ModifiedRouthLyapunov, stationary_motions
    sage: L = load('examples/spherical_pendulum.yaml').lagrangian()
    sage: psi, theta = L.coordinates()
    sage: R = L.routh([psi]); p = R.momenta()[0]
    sage: R.expr()
    1/2*dtheta^2*l^2*m - g*l*m*cos(theta) - 1/2*p_psi^2/(l^2*m*sin(theta)^2)

Its stationary motions (`\dot\theta = 0`, `\partial R/\partial\theta = 0`)
are the conical motions, `p^2 = -g l^3 m^2 \sin^4\theta/\cos\theta`
(`\theta > \pi/2` here: `\theta` is measured from the upward vertical),
all of them stable (Routh's theorem: the amended potential has a minimum)::

    sage: m, l, g = var('m l g')
    sage: sols = stationary_motions(R, solve_for=[p], positive=[m, l, g])
    sage: sols.equations()
    [-(g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(l^2*m*sin(theta)^3)]
    sage: for s in sols: print(s.point(), s.conditions(), s.stability().verdict())
    {p_psi: l*m*sqrt(-g*l/cos(theta))*sin(theta)^2} [cos(theta) < 0, sin(theta) != 0] stable
    {p_psi: -l*m*sqrt(-g*l/cos(theta))*sin(theta)^2} [cos(theta) < 0, sin(theta) != 0] stable

The modified Routh--Lyapunov method: the extended Routh function
`\tilde R = R + p f(\theta)\dot\theta` and its stationarity equations
`\partial\tilde R/\partial\theta = 0`, `\partial\tilde R/\partial\dot\theta = 0`::

    sage: MR = ModifiedRouthLyapunov(R)
    sage: MR.extended_function()
    1/2*dtheta^2*l^2*m - g*l*m*cos(theta) + dtheta*p_psi*f(theta) - 1/2*p_psi^2/(l^2*m*sin(theta)^2)
    sage: MR.stationarity_equations()
    [g*l*m*sin(theta) + dtheta*p_psi*diff(f(theta), theta) + p_psi^2*cos(theta)/(l^2*m*sin(theta)^3),
     dtheta*l^2*m + p_psi*f(theta)]

The second gives `\dot\theta` on the manifold; substituted into the first,
the equations are degenerate (define a curve, an invariant manifold) iff
the first holds for every `\theta` -- the degeneracy condition, an ODE for
`f`::

    sage: MR.velocity_on_manifold()
    -p_psi*f(theta)/(l^2*m)
    sage: MR.degeneracy_condition()
    diff(f(theta), theta) == (g*l^3*m^2*sin(theta)^4 + p_psi^2*cos(theta))/(p_psi^2*f(theta)*sin(theta)^3)

Its general solution (Maxima's ``ode2`` through ``desolve``; ``_C`` is the
constant of integration), solved for `f` exactly -- two branches::

    sage: MR.solve_degeneracy()
    [f(theta) == sqrt(-(2*g*l^3*m^2*cos(theta)^3 - 2*g*l^3*m^2*cos(theta) - 2*_C*cos(theta)^2 - p_psi^2 + 2*_C)/((cos(theta) + 1)*(cos(theta) - 1)))/p_psi,
     f(theta) == -sqrt(-(2*g*l^3*m^2*cos(theta)^3 - 2*g*l^3*m^2*cos(theta) - 2*_C*cos(theta)^2 - p_psi^2 + 2*_C)/((cos(theta) + 1)*(cos(theta) - 1)))/p_psi]

The families of invariant manifolds in explicit form, in the phase plane
`(\theta, \dot\theta)` of the Routh system::

    sage: ims = MR.invariant_manifolds(); ims
    [dtheta == -sqrt(-(2*g*l^3*m^2*cos(theta)^3 - 2*g*l^3*m^2*cos(theta) - 2*_C*cos(theta)^2 - p_psi^2 + 2*_C)/((cos(theta) + 1)*(cos(theta) - 1)))/(l^2*m),
     dtheta == sqrt(-(2*g*l^3*m^2*cos(theta)^3 - 2*g*l^3*m^2*cos(theta) - 2*_C*cos(theta)^2 - p_psi^2 + 2*_C)/((cos(theta) + 1)*(cos(theta) - 1)))/(l^2*m)]

Each is a level set of the energy integral: with `\dot\theta` from an IM,
`(m l^2\dot\theta)^2 + p^2/\sin^2\theta + 2 m^2 g l^3\cos\theta` is the
constant `2\,\_C`::

    sage: dtheta = R.velocities()[0]; m, l, g = var('m l g'); C = var('_C')
    sage: [bool(((m*l^2*im.rhs())^2 + p^2/sin(theta)^2 + 2*m^2*g*l^3*cos(theta)
    ....:         - 2*C).simplify_full() == 0) for im in ims]
    [True, True]

Lifted to the phase space of (9) with the cyclic integral
`m l^2\sin^2\theta\,\dot\psi = p`::

    sage: MR.lifted_manifolds()[0]
    [dtheta == -sqrt(-(2*g*l^3*m^2*cos(theta)^3 - 2*g*l^3*m^2*cos(theta) - 2*_C*cos(theta)^2 - p_psi^2 + 2*_C)/((cos(theta) + 1)*(cos(theta) - 1)))/(l^2*m),
     dpsi == p_psi/(l^2*m*sin(theta)^2)]

Example 4: equilibria of the nonlinear circuit and their stability
==================================================================

The state equations (11) from the circuits part: the right-hand sides of
`L_k \dot i_k = \dots`, `C_l \dot u_l = \dots`::

    sage: from sage_dynsym.analysis import (equilibrium_family, linearize,
    ....:     lienard_chipart_conditions, hurwitz_conditions)
    sage: circuit = load('examples/nonlinear_circuit.yaml')
    sage: x = [v for v, _ in circuit.state_variables()]; x
    [i1, i2, u3, u4, u5, u6]
    sage: rhs = circuit.state_equations(); rhs
    [-u3 + u4 + u6, -u4 + u5, I01 + i1 + f3(u3), -I0 - i1 + i2 + f2(u4), I02 - i2 + f4(u5), -I0 - i1 + f1(u6)]

Time-independent solutions: right-hand sides zero, `u_3, u_5, i_1, i_2`
eliminated (they appear linearly: substitution, no Gröbner basis needed);
two equations in `u_4, u_6` remain::

    sage: i1, i2, u3, u4, u5, u6 = x
    sage: fam = equilibrium_family(rhs, x, eliminate=[u3, u5, i1, i2])
    sage: fam.substitutions()
    {i1: -I0 + f1(u6), i2: I02 + f4(u4), u3: u4 + u6, u5: u4}
    sage: fam.equations()
    [-I0 + I01 + f1(u6) + f3(u4 + u6), I02 - f1(u6) + f2(u4) + f4(u4)]

The source currents making `(u_4^0, u_6^0)` an equilibrium, and the whole
equilibrium point -- a family parametrized by `u_4^0, u_6^0` (and the
characteristics)::

    sage: I0, I01, I02, u40, u60 = var('I0 I01 I02 u40 u60')
    sage: currents = fam.parameters_for({u4: u40, u6: u60}, [I01, I02]); currents
    {I01: I0 - f1(u60) - f3(u40 + u60), I02: f1(u60) - f2(u40) - f4(u40)}
    sage: point = fam.point({u4: u40, u6: u60}, parameters=currents)
    sage: [e.subs(point).subs(currents) for e in rhs]
    [0, 0, 0, 0, 0, 0]

The cubic characteristics `f_j(u) = g_j u (u - 3 s_j)^2` (first extremum
at `s_j`), specialised to `s_2 = s_3 = s_4 = 2 s_1`, `g_2 = g_3 = g_4 =
g_1`, `L_2 = L_1`, `C_2 = C_3 = C_4 = C_1`, at `u_4^0 = u_6^0 = 2 s_1`::

    sage: g1, s1 = var('g1 s1'); L1, L2, C1, C2, C3, C4 = var('L1 L2 C1 C2 C3 C4')
    sage: s = {1: s1, 2: 2*s1, 3: 2*s1, 4: 2*s1}
    sage: f = {j: function('f%d' % j) for j in (1, 2, 3, 4)}
    sage: def cubic(e):
    ....:     for j in f:
    ....:         e = SR(e).substitute_function(f[j], lambda u, j=j: g1*u*(u - 3*s[j])^2)
    ....:     return e
    sage: same = {L2: L1, C2: C1, C3: C1, C4: C1}
    sage: at = {u40: 2*s1, u60: 2*s1}
    sage: pt = {v: cubic(e).subs(at) for v, e in point.items()}
    sage: src = {k: cubic(e).subs(at) for k, e in currents.items()}; src
    {I01: -18*g1*s1^3 + I0, I02: -62*g1*s1^3}
    sage: pt = {v: e.subs(src) for v, e in pt.items()}; pt
    {i1: 2*g1*s1^3 - I0, i2: -30*g1*s1^3, u3: 4*s1, u4: 2*s1, u5: 2*s1, u6: 2*s1}

First approximation `B\dot\xi = J\xi`, `B = \mathrm{diag}(L_1, L_2, C_3,
C_2, C_4, C_1)` (the order of the state variables); the equations are
printed with the deviations named like the state variables (``di1`` is
`\dot\xi_{i_1}`). At this point `f_2' = f_4' = 0`, `f_1' = -3 g_1 s_1^2`,
`f_3' = -12 g_1 s_1^2`::

    sage: B = [SR(name).subs(same) for _, name in circuit.state_variables()]; B
    [L1, L1, C1, C1, C1, C1]
    sage: lin = linearize([cubic(e).subs(src) for e in rhs], pt, x, lhs_matrix=B)
    sage: lin.equations()
    [L1*di1 + u3 - u4 - u6,
     L1*di2 + u4 - u5,
     12*g1*s1^2*u3 + C1*du3 - i1,
     C1*du4 + i1 - i2,
     C1*du5 + i2,
     3*g1*s1^2*u6 + C1*du6 + i1]

The characteristic polynomial `\det(B\lambda - J)`, with
`\rho = f_1(s_1)/s_1 = 4 g_1 s_1^2`::

    sage: lam, rho = var('lam rho')
    sage: chi = lin.characteristic_polynomial(lam).subs(g1=rho/(4*s1^2)).expand(); chi
    C1^4*L1^2*lam^6 + 15/4*C1^3*L1^2*lam^5*rho + 9/4*C1^2*L1^2*lam^4*rho^2 + 5*C1^3*L1*lam^4 + 15*C1^2*L1*lam^3*rho + 27/4*C1*L1*lam^2*rho^2 + 5*C1^2*lam^2 + 45/4*C1*lam*rho + 9/4*rho^2

The Liénard--Chipart conditions (the leading coefficient `C_1^4 L_1^2`
is positive and drops out); given `C_1 > 0`, `L_1 > 0`, `\rho > 0` all of
them hold -- the equilibrium is asymptotically stable::

    sage: lienard_chipart_conditions(chi, lam)
    [(27*L1*rho^2 + 20*C1)*C1,
     (9*L1*rho^2 + 20*C1)*L1,
     C1*rho,
     (9*L1*rho^2 + 8*C1)*C1,
     (9*L1*rho^2 + 4*C1)*(3*L1*rho^2 + 4*C1)*C1*rho]
    sage: lienard_chipart_conditions(chi, lam, positive=[C1, L1, rho])
    []

Check with numerical eigenvalues at one point::

    sage: J = lin.jacobian().subs(g1=rho/(4*s1^2)).subs(C1=1, L1=2, rho=1/3, s1=1)
    sage: max(e.real() for e in J.change_ring(CDF).eigenvalues()) < 0
    True

Textbook results
================

**Double pendulum** (Merkin, *Introduction to the theory of stability*,
ch. 3 and 6): of the four equilibria only the lower one is stable; the
others have a degree of instability 1 or 2 (Kelvin--Chetaev)::

    sage: from sage_dynsym import MechanicalSystem, RigidBody, UniformGravity
    sage: th1, th2, m1, m2, l1, l2, g = var('theta1 theta2 m1 m2 l1 l2 g')
    sage: b1 = RigidBody('b1', rotations=[(1, th1)], mass_center=[0, 0, -l1], mass=m1,
    ....:                inertia=diagonal_matrix([m1*l1^2, m1*l1^2, 0]))
    sage: b2 = RigidBody('b2', parent=1, rotations=[(1, th2 - th1)], joint=[0, 0, -l1],
    ....:                mass_center=[0, 0, -l2], mass=m2,
    ....:                inertia=diagonal_matrix([m2*l2^2, m2*l2^2, 0]))
    sage: dp = MechanicalSystem([b1, b2], [th1, th2], parameters=[m1, m2, l1, l2, g],
    ....:                       force_function=UniformGravity([0, 0, -g])).lagrangian()
    sage: eq = stationary_motions(dp, positive=[m1, m2, l1, l2, g]); eq.equations()
    [g*l1*(m1 + m2)*sin(theta1), g*l2*m2*sin(theta2)]
    sage: for s in eq: print(s.point(), s.stability().verdict(), s.stability().method())
    {theta1: 0, theta2: 0} stable Routh-Lyapunov
    {theta1: 0, theta2: pi} unstable first approximation
    {theta1: pi, theta2: 0} unstable first approximation
    {theta1: pi, theta2: pi} unstable first approximation
    sage: for q0 in [(0, 0), (0, pi), (pi, 0), (pi, pi)]:
    ....:     lin = linearize(dp, {th1: q0[0], th2: q0[1]})
    ....:     print(q0, lin.kelvin_chetaev(positive=[m1, m2, l1, l2, g]).verdict())
    (0, 0) stable
    (0, pi) unstable
    (pi, 0) unstable
    (pi, pi) unstable

**Heavy symmetric top, sleeping top** (Merkin, ch. 6; Chetaev): a top with
moments of inertia `A, A, C` about its fixed point, centre of mass at
distance `l` on the axis, described by the angles `\alpha, \beta` of the
axis and the proper rotation `\varphi` (cyclic). The upright rotation is an
equilibrium of the Routh system with an even degree of instability (2);
gyroscopic stabilization happens iff `p^2 > 4 A m g l`, `p = C\omega`: the
classical condition `C^2\omega^2 > 4 A m g l`::

    sage: alpha, beta, phi, A, C, m, l = var('alpha beta phi A C m l')
    sage: top = RigidBody('top', rotations=[(1, alpha), (2, beta), (3, phi)],
    ....:                 mass_center=[0, 0, l], mass=m, inertia=diagonal_matrix([A, A, C]))
    sage: Lt = MechanicalSystem([top], [alpha, beta, phi], parameters=[A, C, m, g, l],
    ....:                       force_function=UniformGravity([0, 0, -g])).lagrangian()
    sage: Rt = Lt.routh([phi]); p = Rt.momenta()[0]
    sage: lin = linearize(Rt, {alpha: 0, beta: 0})
    sage: lin.M(), lin.G(), lin.K()
    (
    [A 0]  [         0  1/2*p_phi]  [-g*l*m      0]
    [0 A], [-1/2*p_phi          0], [     0 -g*l*m]
    )
    sage: v = lin.kelvin_chetaev(positive=[A, C, m, g, l]); v.verdict()
    'depends on the parameters'
    sage: for case in v.cases(): print(case.verdict(), case.region())
    stable in first approximation [[4*A*g*l*m - p_phi^2 < 0]]
    unstable [[4*A*g*l*m - p_phi^2 > 0]]

With dissipation in both angles
the stabilization is destroyed::

    sage: c = var('c')
    sage: from sage_dynsym.analysis import kelvin_chetaev
    sage: kelvin_chetaev(lin.M(), c*identity_matrix(2), lin.G(), lin.K(),
    ....:                positive=[A, C, m, g, l, c]).verdict()
    'unstable'

**Hurwitz test on polynomials with known roots**: see
:mod:`sage_dynsym.analysis.hurwitz`.
"""

__all__ = []
