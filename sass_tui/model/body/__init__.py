"""The body: the figure SASS holds (global data and one state per group), its
landmarks, the lofted surface through the person's own measurements, the HAnim
skeleton and its segments, a posture of it, and its outline on screen.

May import: the model's top (units, vocabulary, names, errors, text, datasets)
and model.population's percentile model.  Never the strength or file rooms."""
