"""Populations from the database: target and virtual populations, population
files, manikin families, fit tests, percentile tables, the prediction model
and the people of a task.

May import: the model, db.engine, db.query and db.people."""
