"""The database layer: the only place that knows an engine, a connection or a
lock.  Rooms: engine/, query/, people/, populations/; progress at the top."""
