"""Populations: the percentile model, prediction of unmeasured values,
target populations (survey weights), virtual populations, accommodation and
manikin families, and design limits.

May import: the model's top (units, vocabulary, names, errors, datasets)."""
