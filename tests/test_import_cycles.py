"""Import hygiene: no import cycle between the modules of sass_tui, of any length."""

from __future__ import annotations

import grimp


def strongly_connected(graph: dict[str, set[str]]) -> list[list[str]]:
    """The groups of modules that reach each other through imports (Tarjan's
    algorithm, iterative so a deep chain cannot exhaust the stack); a group of
    more than one module is a cycle."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    groups: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                groups.append(sorted(group))
    return groups


def test_the_cycle_finder_finds_a_long_cycle_and_nothing_else():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"d"}, "d": {"a"}, "e": {"a"}, "f": set()}
    assert [g for g in strongly_connected(graph) if len(g) > 1] == [["a", "b", "c", "d"]]
    assert [g for g in strongly_connected({"a": {"b"}, "b": set()}) if len(g) > 1] == []


def test_no_import_cycle_between_modules():
    """No module reaches itself through imports, at the top of a module or
    inside a function (an import only for type checking does not run, and does
    not count): a cycle of any length, not only two modules importing each other."""
    graph = grimp.build_graph("sass_tui", exclude_type_checking_imports=True, cache_dir=None)
    imports = {
        module: {
            m for m in graph.find_modules_directly_imported_by(module) if m.startswith("sass_tui")
        }
        for module in graph.modules
        if module.startswith("sass_tui")
    }
    cycles = [group for group in strongly_connected(imports) if len(group) > 1]
    assert cycles == []
