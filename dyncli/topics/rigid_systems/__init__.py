"""Systems of rigid bodies and point masses with massless links (notes §36)."""
