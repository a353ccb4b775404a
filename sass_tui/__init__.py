"""sass: the Spreadsheet Anthropometry Scaling System in a terminal.  Four layers,
each split into topic packages: docs/architecture.md draws them."""
