"""Import hygiene: no two modules of sass_tui import each other."""

from __future__ import annotations


def test_no_module_imports_one_that_imports_it_back():
    """No two modules of sass_tui import each other, at the top or inside a
    function (an import only for type checking does not run, and does not count)."""
    import grimp

    graph = grimp.build_graph("sass_tui", exclude_type_checking_imports=True, cache_dir=None)
    both_ways = sorted(
        (a, b)
        for a in graph.modules
        for b in graph.find_modules_directly_imported_by(a)
        if a < b and a in graph.find_modules_directly_imported_by(b)
    )
    assert both_ways == []
