"""`dyncli check`: grade answer files against solved problems (contract §5)."""
