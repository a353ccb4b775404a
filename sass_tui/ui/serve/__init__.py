"""`sass serve`: the app in a web browser through textual-serve, one process
per browser session, and the page it serves.

May import: the model and ui's top; never a screen."""
