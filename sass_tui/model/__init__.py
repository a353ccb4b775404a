"""The model: pure Python and numpy, no Textual, no database engine.  At its top,
the vocabulary every room uses (units, names, errors, text, measures, data sets)
and the Session; the rooms are body/, population/, strength/ and files/."""
