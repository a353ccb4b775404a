"""The engines: the Database service (the one owner of a connection and its
lock), the SQLite schema, PostgreSQL, what differs between them, and what
`--db` names.

May import: the model only."""
