"""The anthropometric spreadsheet (report §12.2): its pages, editing, files,
worksheets, the strength page and its Task panel, the figure drawn beside it,
and the commands and exports it offers.

May import: the model, the database layer, ui's top and ui.widgets."""
