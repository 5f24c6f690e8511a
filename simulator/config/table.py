"""The base of every schema model: one TOML table with a fixed set of keys."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, model_validator
from pydantic_core import PydanticCustomError

from simulator.config.errors import unknown_key

__all__ = ["Table"]


class Table(BaseModel):
    """A TOML table: its keys are the model's fields, in the order they are declared.

    A key that is not a field is an error on that key (checked before any
    value, so it is what a table with several problems reports), worded by
    :meth:`key_not_allowed`. Values are strict (see
    :mod:`simulator.config.fields`); models are frozen.
    """

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)

    @model_validator(mode="before")
    @classmethod
    def _known_keys(cls, data: Any) -> Any:
        if isinstance(data, dict):
            for key in data:
                if key not in cls.model_fields:
                    raise cls.key_not_allowed(key)
        return data

    @classmethod
    def key_not_allowed(cls, key: str) -> PydanticCustomError:
        """The error for ``key``, which this table does not take."""
        return unknown_key(key, tuple(cls.model_fields))
