"""Exceptions and warnings of osc2cr (plain Python classes, so they pickle across processes)."""

from __future__ import annotations

import errno


class ConversionError(Exception):
    """A scenario could not be converted.

    Attributes:
        message: the full message (with the position, when known).
        file: the file the problem is in (the scenario, its road network, a catalog, ...).
        line: 1-based line in ``file``, or None when the problem has no single place.
        column: 1-based column in ``file``, or None.
        stage: the pipeline stage that failed: ``load``, ``road_network``, ``map``,
            ``engine``, ``build``, ``write`` or ``timeout``.
        variation: the 1-based variation of a parameter distribution, or None.
    """

    def __init__(
        self,
        message: str,
        file: str | None = None,
        line: int | None = None,
        column: int | None = None,
        stage: str | None = None,
        variation: int | None = None,
    ) -> None:
        super().__init__(message, file, line, column, stage, variation)
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        self.stage = stage
        self.variation = variation

    def __str__(self) -> str:
        return self.message


class ScenarioNotFoundError(ConversionError, FileNotFoundError):
    """The scenario file given does not exist: a :class:`ConversionError` (same attributes) that
    is also the ``FileNotFoundError`` Python raises for a missing file (``errno`` ENOENT,
    ``filename`` the path)."""

    def __init__(self, *args: object, **kwargs: object) -> None:
        # ConversionError's arguments; the OSError attributes follow from them
        ConversionError.__init__(self, *args, **kwargs)  # type: ignore[arg-type]
        self.errno = errno.ENOENT
        self.strerror = "No such file or directory"
        self.filename = self.file


class ConversionWarning(UserWarning):
    """Something the converter accepted but the user should know about (an element only
    partly modelled, a controller replaced, ...). Silence with
    ``warnings.simplefilter("ignore", osc2cr.ConversionWarning)``."""
