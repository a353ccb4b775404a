"""Strength: the strength page's data and conditions, published strength
models (Anderson et al. 2007, the Arm Force Field, grip), percent capable over
many people, tasks (a posture and its loads), manual handling and the low back.

May import: the model's top, model.body and model.population."""
