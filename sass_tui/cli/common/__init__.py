"""What more than one verb of the command line shares: the database a verb
names, the options of the figure and the database, `--person`, and progress
on the terminal.

May import: the model and the database layer; never Textual, never a verb."""
