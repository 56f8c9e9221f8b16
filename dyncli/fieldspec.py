"""What a field factory of :mod:`dyncli.fields` returns: the metadata of one declaration
``x: Annotated[float, Num(gt=0)]``, a form a type checker reads (the field is a plain ``float`` to
mypy) where a call in the type's place (``x: Num(gt=0)``) is not one."""

from __future__ import annotations

from typing import Any, Callable, Iterator

from annotated_types import GroupedMetadata
from pydantic import ValidationInfo
from pydantic.functional_validators import PlainValidator
from pydantic.json_schema import WithJsonSchema


class FieldSpec(GroupedMetadata):
    """A field factory's result, the metadata of ``Annotated[<type>, spec]``: pydantic expands it (grouped
    metadata) into ``PlainValidator`` and ``WithJsonSchema``; :mod:`dyncli.angles` reads ``json_schema``."""

    def __init__(self, validate: Callable[[Any, ValidationInfo], Any] | None, json_schema: dict[str, Any]) -> None:
        self.validate, self.json_schema = validate, json_schema

    def __iter__(self) -> Iterator[Any]:
        if self.validate is not None:
            yield PlainValidator(self.validate)
        yield WithJsonSchema(self.json_schema)
