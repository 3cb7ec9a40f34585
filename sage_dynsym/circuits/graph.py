r"""
The circuit graph: spanning trees and fundamental loops

Nodes are vertices, every elementary branch is one edge of a Sage
``Graph(multiedges=True)`` labelled by the branch's position, so parallel
branches are distinct edges. Independent loops are the *fundamental
cycles* of a spanning tree (a cycle basis of the graph), never faces of a
drawing: non-planar circuits are handled like any other.

EXAMPLES::

    sage: from sage_dynsym.circuits.elements import parse_entries
    sage: from sage_dynsym.circuits.graph import CircuitGraph
    sage: branches, _ = parse_entries([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1'], [1, 3, 'E1']])
    sage: CG = CircuitGraph(branches)
    sage: tree = CG.spanning_tree(rank=lambda b: b.tree_rank)    # the normal tree
    sage: sorted(tree)
    [1, 3]
    sage: T = CG.rooted(tree)
    sage: [(b.name, s) for b, s in T.loop(branches[0])]
    [('R1', 1), ('C1', 1), ('E1', -1)]
"""
from sage.graphs.graph import Graph

from ..errors import CircuitError

__all__ = ['UnionFind', 'node_key', 'capacitor_order', 'CircuitGraph', 'RootedTree']


class UnionFind:
    r"""
    Disjoint sets of nodes (used to grow forests such as the
    capacitor/voltage-source forest).

    EXAMPLES::

        sage: from sage_dynsym.circuits.graph import UnionFind
        sage: U = UnionFind([1, 2, 3])
        sage: U.union(1, 2), U.union(2, 1), U.find(1) == U.find(2)
        (True, False, True)
    """

    def __init__(self, nodes):
        self._parent = {v: v for v in nodes}

    def find(self, v):
        r"""The representative of the set of ``v``.

        EXAMPLES::

            sage: from sage_dynsym.circuits.graph import UnionFind
            sage: U = UnionFind([1, 2, 3]); U.union(1, 2)
            True
            sage: U.find(1) == U.find(2), U.find(3)
            (True, 3)
        """
        root = v
        while self._parent[root] != root:
            root = self._parent[root]
        while self._parent[v] != root:     # path compression
            self._parent[v], v = root, self._parent[v]
        return root

    def union(self, a, b):
        r"""Join the sets of ``a`` and ``b``; return ``False`` if they were one set.

        EXAMPLES::

            sage: from sage_dynsym.circuits.graph import UnionFind
            sage: U = UnionFind([1, 2, 3])
            sage: U.union(1, 2), U.union(2, 1), U.union(3, 1)
            (True, False, True)
        """
        ra, rb = self.find(a), self.find(b)
        if ra == rb:
            return False
        self._parent[ra] = rb
        return True


def node_key(v):
    r"""
    Sort key for nodes that may mix integers and names (integers first).

    EXAMPLES::

        sage: from sage_dynsym.circuits.graph import node_key
        sage: sorted(['b', 3, 'a', 1], key=node_key)
        [1, 3, 'a', 'b']
    """
    return (isinstance(v, str), v)


def capacitor_order(cgraph):
    r"""
    The capacitors (branch positions) in the naming order of the state
    variables: breadth-first through the capacitor forest, each tree of it
    started at its highest node (trees taken from the highest such node
    down), neighbours visited in increasing node order; capacitors closing
    a loop of capacitors come last, in branch order.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: from sage_dynsym.circuits.graph import CircuitGraph, capacitor_order
        sage: CG = CircuitGraph(parse_entries([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'C3'],
        ....:                                  [1, 3, 'L1']])[0])
        sage: [CG.branches[p].name for p in capacitor_order(CG)]
        ['C3', 'C2', 'C1']
    """
    adjacency = {v: [] for v in cgraph.nodes}
    for p, b in enumerate(cgraph.branches):
        if b.is_capacitive():
            adjacency[b.tail].append((b.head, p))
            adjacency[b.head].append((b.tail, p))
    order, seen = [], set()
    for root in reversed(cgraph.nodes):
        if root in seen or not adjacency[root]:
            continue
        seen.add(root)
        queue = [root]
        for v in queue:
            for w, p in sorted(adjacency[v], key=lambda e: (node_key(e[0]), e[1])):
                if w not in seen:
                    seen.add(w)
                    order.append(p)
                    queue.append(w)
    return order + [p for p, b in enumerate(cgraph.branches)
                    if b.is_capacitive() and p not in order]


class CircuitGraph:
    r"""
    The graph of a circuit, with its branches.

    INPUT:

    - ``branches`` -- tuple of :class:`~sage_dynsym.circuits.elements.kinds.Branch`
    - ``links`` -- (optional) pairs of branch positions coupled by a mutual
      inductance: parts of the graph joined only by such a coupling (a
      transformer with galvanically isolated sides) form one circuit

    Raises :class:`~sage_dynsym.errors.CircuitError` for a self-loop or a
    graph whose parts are joined neither by branches nor by couplings.

    TESTS::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: from sage_dynsym.circuits.graph import CircuitGraph
        sage: CircuitGraph(parse_entries([[1, 2, 'R1'], [2, 2, 'C1']])[0])
        Traceback (most recent call last):
        ...
        CircuitError: branches[1]: self-loop: branch C1 joins node 2 to itself
        sage: CircuitGraph(parse_entries([[1, 2, 'R1'], [3, 4, 'C1']])[0])
        Traceback (most recent call last):
        ...
        CircuitError: the circuit graph is disconnected: its parts have nodes [1, 2] and [3, 4] (parts may be joined only through mutual inductances)

    Two windings coupled by a mutual inductance only::

        sage: CG = CircuitGraph(parse_entries([[1, 2, 'L1'], [3, 4, 'L2']])[0], links=[(0, 1)])
        sage: CG.graph.connected_components_number()
        2
    """

    def __init__(self, branches, links=()):
        self.branches = tuple(branches)
        graph = Graph(multiedges=True, loops=False)
        for pos, b in enumerate(self.branches):
            if b.tail == b.head:
                raise CircuitError(f"self-loop: branch {b.name} joins node "
                                   f"{b.tail} to itself", entry=f"branches[{b.index}]")
            graph.add_edge(b.tail, b.head, pos)
        if graph.num_verts() == 0:
            raise CircuitError("a circuit needs at least one branch", entry="branches")
        joined = UnionFind(graph.vertices(sort=False))
        for part in graph.connected_components(sort=False):
            for v in part[1:]:
                joined.union(part[0], v)
        for a, b in links:
            joined.union(self.branches[a].tail, self.branches[b].tail)
        if len({joined.find(v) for v in graph.vertices(sort=False)}) > 1:
            parts = sorted((sorted(c, key=node_key) for c in graph.connected_components()),
                           key=lambda c: node_key(c[0]))
            raise CircuitError("the circuit graph is disconnected: its parts have "
                               f"nodes {' and '.join(map(str, parts))} (parts may be "
                               "joined only through mutual inductances)")
        self.graph = graph.copy(immutable=True)
        self.nodes = tuple(sorted(graph.vertices(sort=False), key=node_key))

    def __repr__(self):
        return f"Circuit graph with {len(self.branches)} branches on {len(self.nodes)} nodes"

    def spanning_tree(self, rank=None, keep=None):
        r"""
        Return a spanning tree (a spanning forest when the graph has
        several parts) as a set of branch positions.

        INPUT:

        - ``rank`` -- (optional) a function of a branch, a number: branches
          of lower rank are preferred (for instance the normal tree's
          :attr:`~sage_dynsym.circuits.elements.kinds.Branch.tree_rank`);
          by default all alike
        - ``keep`` -- (optional) a predicate on branches: the branches it
          refuses are never taken; by default all may be

        Kruskal's algorithm (Sage's ``min_spanning_tree``), ties broken by
        branch order. Returns ``None`` when the kept branches do not
        connect the nodes of each part.

        EXAMPLES: by :attr:`~sage_dynsym.circuits.elements.kinds.Branch.tree_rank`
        (capacitors before inductors), and without current sources::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: CG = CircuitGraph(parse_entries([[1, 2, 'L1'], [1, 2, 'C1'], [2, 3, 'I1']])[0])
            sage: sorted(CG.spanning_tree(rank=lambda b: b.tree_rank)), sorted(CG.spanning_tree())
            ([1, 2], [0, 2])
            sage: CG.spanning_tree(keep=lambda b: b.fixed_current() is None) is None
            True
        """
        m = len(self.branches)
        kept = [(b.tail, b.head, pos) for pos, b in enumerate(self.branches)
                if keep is None or keep(b)]
        sub = Graph(kept, multiedges=True, loops=False, format='list_of_edges')
        sub.add_vertices(self.nodes)
        if sub.connected_components_number() != self.graph.connected_components_number():
            return None
        weight = {pos: (0 if rank is None else rank(self.branches[pos])) * m + pos
                  for _, _, pos in kept}
        tree = sub.min_spanning_tree(weight_function=lambda e: weight[e[2]],
                                     algorithm='Kruskal')
        return {e[2] for e in tree}

    def rooted(self, tree):
        r"""
        The spanning tree ``tree`` (set of branch positions) as a
        :class:`RootedTree`, rooted at the last node.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: br, _ = parse_entries([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1']])
            sage: T = CircuitGraph(br).rooted({0, 1})
            sage: [(b.name, s) for b, s in T.path(1, 3)]
            [('R1', 1), ('C1', 1)]
            sage: [(b.name, s) for b, s in T.loop(br[2])]
            [('L1', 1), ('R1', 1), ('C1', 1)]
        """
        return RootedTree(self, tree)

    def components(self, positions):
        r"""
        Union-find of the nodes joined by the branches at ``positions``;
        raises ``ValueError`` with the offending position if they contain a
        cycle.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: CG = CircuitGraph(parse_entries([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1']])[0])
            sage: U = CG.components([0, 1]); U.find(1) == U.find(3)
            True
            sage: CG.components([0, 1, 2])
            Traceback (most recent call last):
            ...
            ValueError: 2
        """
        uf = UnionFind(self.nodes)
        for pos in positions:
            b = self.branches[pos]
            if not uf.union(b.tail, b.head):
                raise ValueError(pos)
        return uf

    def check_source_loops(self):
        r"""
        Refuse a loop of voltage sources alone (Kirchhoff's voltage law
        would fix a sum of source values).

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: CircuitGraph(parse_entries([[1, 2, 'E1'], [2, 1, 'R1']])[0]).check_source_loops()
            sage: CircuitGraph(parse_entries([[1, 2, 'E1'], [2, 1, 'E2']])[0]).check_source_loops()
            Traceback (most recent call last):
            ...
            CircuitError: the voltage sources E2, E1 form a loop: Kirchhoff's voltage law cannot hold for arbitrary source values
        """
        sources = [p for p, b in enumerate(self.branches) if b.fixed_voltage() is not None]
        try:
            self.components(sources)
        except ValueError as err:
            loop = self.cycle_through(sources[:sources.index(err.args[0])], err.args[0])
            raise CircuitError(f"the voltage sources {', '.join(loop)} form a loop: "
                               "Kirchhoff's voltage law cannot hold for arbitrary "
                               "source values") from err

    def cycle_through(self, positions, pos):
        r"""
        A cycle made of the branch ``pos`` and branches of ``positions``
        (which must join its ends), as a list of branch names.

        EXAMPLES::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: CG = CircuitGraph(parse_entries([[1, 2, 'C1'], [2, 3, 'C2'], [3, 1, 'E1']])[0])
            sage: CG.cycle_through([0, 1], 2)
            ['E1', 'C1', 'C2']
        """
        sub = [(self.branches[p].tail, self.branches[p].head, p) for p in positions]
        forest = Graph(sub, multiedges=True, loops=False, format='list_of_edges')
        b = self.branches[pos]
        path = forest.shortest_path(b.head, b.tail, by_weight=False)
        names = [b.name]
        for x, y in zip(path, path[1:]):
            names.append(self.branches[min(forest.edge_label(x, y))].name)
        return names


class RootedTree:
    r"""
    A spanning tree (or forest, each tree rooted at its highest node) with
    parent pointers, for fundamental loops and paths.

    ``path(a, b)`` is the list of ``(branch, sign)`` met when walking in the
    tree from node ``a`` to node ``b``, with ``sign = +1`` when a branch is
    walked along its orientation. ``loop(chord)`` is the fundamental loop of
    a branch outside the tree, oriented along that branch and starting with
    it.

    EXAMPLES::

        sage: from sage_dynsym.circuits.elements import parse_entries
        sage: from sage_dynsym.circuits.graph import CircuitGraph
        sage: branches, _ = parse_entries([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1'], [1, 3, 'E1']])
        sage: CG = CircuitGraph(branches)
        sage: T = CG.rooted(CG.spanning_tree(rank=lambda b: b.tree_rank))
        sage: [branches[k].name for k in sorted(T.positions)]
        ['C1', 'E1']
        sage: [(b.name, s) for b, s in T.path(2, 1)]    # along C1, against E1
        [('C1', 1), ('E1', -1)]
    """

    def __init__(self, cgraph, tree):
        self.positions = frozenset(tree)
        branches = cgraph.branches
        adjacency = {v: [] for v in cgraph.nodes}
        for pos in sorted(tree):
            b = branches[pos]
            adjacency[b.tail].append((b.head, pos))
            adjacency[b.head].append((b.tail, pos))
        self.parent, self.depth = {}, {}   # node -> (parent node, branch position)
        for root in reversed(cgraph.nodes):     # one root per part of a forest
            if root in self.parent:
                continue
            self.parent[root], self.depth[root] = None, 0
            queue = [root]
            for v in queue:
                for w, pos in adjacency[v]:
                    if w not in self.parent:
                        self.parent[w] = (v, pos)
                        self.depth[w] = self.depth[v] + 1
                        queue.append(w)
        self._branches = branches

    def _step(self, v):
        # the tree branch from v to its parent, with the sign of that walk
        parent, pos = self.parent[v]
        b = self._branches[pos]
        return parent, (b, 1 if b.tail == v else -1)

    def path(self, a, b):
        r"""The tree path from node ``a`` to node ``b``: a list of ``(branch, sign)``.

        EXAMPLES: the tree of the module's example: ``C1`` (from node 2 to
        3) and ``E1`` (from 1 to 3)::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: branches, _ = parse_entries([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1'], [1, 3, 'E1']])
            sage: CG = CircuitGraph(branches)
            sage: T = CG.rooted(CG.spanning_tree(rank=lambda b: b.tree_rank))
            sage: [(b.name, s) for b, s in T.path(1, 2)]
            [('E1', 1), ('C1', -1)]
        """
        up, down = [], []
        while self.depth[a] > self.depth[b]:
            a, step = self._step(a)
            up.append(step)
        while self.depth[b] > self.depth[a]:
            b, (br, s) = self._step(b)
            down.append((br, -s))
        while a != b:
            a, step = self._step(a)
            up.append(step)
            b, (br, s) = self._step(b)
            down.append((br, -s))
        return up + down[::-1]

    def loop(self, chord):
        r"""The fundamental loop of ``chord``, oriented along it, starting with it.

        EXAMPLES: the tree of the module's example: ``C1`` (from node 2 to
        3) and ``E1`` (from 1 to 3)::

            sage: from sage_dynsym.circuits.elements import parse_entries
            sage: from sage_dynsym.circuits.graph import CircuitGraph
            sage: branches, _ = parse_entries([[1, 2, 'R1'], [2, 3, 'C1'], [3, 1, 'L1'], [1, 3, 'E1']])
            sage: CG = CircuitGraph(branches)
            sage: T = CG.rooted(CG.spanning_tree(rank=lambda b: b.tree_rank))
            sage: [(b.name, s) for b, s in T.loop(branches[0])]     # R1
            [('R1', 1), ('C1', 1), ('E1', -1)]
            sage: [(b.name, s) for b, s in T.loop(branches[2])]     # L1
            [('L1', 1), ('E1', 1)]
        """
        return [(chord, 1)] + self.path(chord.head, chord.tail)
