"""People in the database: importing ANSUR II and flat files, storing people
in bulk, the default database and its people, one person with every value,
and values of many people as a matrix.

May import: the model, db.engine and db.query."""
