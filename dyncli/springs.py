"""The one rule every one-sided spring of dyncli shares (``one_sided: compression|tension`` in
particle, constrained-particle and rectilinear): a compression-only spring acts while shorter than
its free length, so it needs one."""

from __future__ import annotations


def one_sided_length(one_sided: str | None, L: float) -> None:
    """ValueError (the model's field message) for a compression-only spring of free length 0."""
    if one_sided == "compression" and L == 0:
        raise ValueError("one_sided: compression needs a free length L > 0 (the spring acts while shorter "
                         "than L): give L")
