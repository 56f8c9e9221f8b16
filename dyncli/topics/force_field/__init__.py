"""Force fields: curl, conservative verdict, potential and work along a path (notes §19)."""
