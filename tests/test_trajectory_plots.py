"""Trajectories with many coordinates are plotted in readable groups: the
positions and the velocities in separate panels, at most CURVES_PER_PANEL
curves each, the legend outside the axes (checked on the Matplotlib figure:
the legend's box lies right of the axes' box), while T.plot(var) still draws
the chosen variables in one picture."""
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from sage.all import var

from sage_dynsym.analysis.motion import SecondOrderEquations
from sage_dynsym.numerics.simulate import simulate
from sage_dynsym.numerics.trajectory import Trajectory, CURVES_PER_PANEL


def chain(n):
    # n unit masses between unit springs, fixed at both ends
    q = [var(f'x{k}') for k in range(n)]
    dq = [var(f'dx{k}') for k in range(n)]
    ddq = [var(f'ddx{k}') for k in range(n)]
    ends = [0] + q + [0]
    E = [ddq[k] + 2 * q[k] - ends[k] - ends[k + 2] for k in range(n)]
    return SecondOrderEquations(E, q, dq, ddq), q, dq


def legend_outside(G):
    figure = G.matplotlib()
    FigureCanvasAgg(figure)
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    axes, = figure.axes
    legend = axes.get_legend()
    return legend.get_window_extent(renderer).x0 >= axes.get_window_extent(renderer).x1


def test_positions_and_velocities_in_separate_panels_with_the_legend_outside():
    E, q, dq = chain(7)
    initial = {x: 0 for x in q + dq}
    initial[q[0]] = 1
    T = simulate(E, {}, initial, 2)
    A = T.plot()
    panels = list(A)
    assert len(panels) == 2
    # one curve per variable, the positions first
    assert [len(P) for P in panels] == [7, 7]
    assert [P.axes_labels()[1] for P in panels] == ['positions', 'velocities']
    assert all(legend_outside(P) for P in panels)
    # the chosen variables in one picture, as before
    G = T.plot(q[0], dq[0])
    assert len(G) == 2 and legend_outside(G)
    assert len(T.plot(q[0])) == 1


def test_a_large_group_is_split():
    n = CURVES_PER_PANEL + 3
    variables = [var(f'u{k}') for k in range(n)]          # first order: no velocities
    times = np.linspace(0, 1, 5)
    T = Trajectory(times, np.outer(times, np.arange(n)), variables, {})
    assert [len(P) for P in T.plot()] == [CURVES_PER_PANEL, 3]
