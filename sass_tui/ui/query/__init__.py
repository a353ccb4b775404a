"""The database query spreadsheet (report §12.3): its list, builder, commands,
imports, and the screens it opens (Fit Test, Stats, Family, Person, target
picker).

May import: the model, the database layer, ui's top and ui.widgets."""
