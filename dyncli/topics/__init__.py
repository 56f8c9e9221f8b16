"""Topic packages: one per physical topic (model.py = input model, solver.py = numeric core)."""
