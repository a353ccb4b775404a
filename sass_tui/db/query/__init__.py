"""The query language (spec §4): its grammar, generated parser and one typed
tree, the fields, which people a query reaches, the SQL it compiles to, the
query lists, and the DuckDB column copy that counts over millions of people.

May import: the model and db.engine."""
