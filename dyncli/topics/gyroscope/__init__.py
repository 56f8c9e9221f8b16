"""The gyroscope of §37: theta(t) of (37.12) and the moments of Table 37.1."""
