"""osc2cr: OpenSCENARIO (+ OpenDRIVE) to CommonRoad, natively (Rust), in milliseconds.

    import osc2cr
    scenario, problems = osc2cr.convert("cut_in.xosc", dt=0.1)   # commonroad-io objects
    xml = osc2cr.convert_to_xml("cut_in.xosc")                  # CommonRoad 2020a XML text
    for v in osc2cr.variations("cut-in_parameter_set.xosc"):    # lazy: one at a time
        print(v.index, v.parameters, len(v.xml))

    sim = osc2cr.Simulation("cut-in.xosc", external=["Ego"])   # closed loop
    obs = sim.reset()                                           # commonroad-io objects
    while not sim.done:
        obs = sim.step({"Ego": my_planner(obs)})                # a state or DriverInput
    scenario, problems = sim.to_commonroad()                    # the run as driven

:class:`Simulation` (closed loop) is described in its docstring and in ``osc2cr._simulation``;
``osc2cr.gym`` wraps it as a Gymnasium environment (``pip install osc2cr[gym]``).

Options (keyword arguments of every function) are ``osc2cr convert``'s long options with
``_`` for ``-``; an option left out (or None) keeps the CLI's default:

    dt (0.1 s), step (0.01 s), max_time (60 s), ego (exact entity name), ego_pattern ("ego"),
    drop_ego (False), params ({name: value} global parameters), goal_length (50 m),
    goal_width (10 m), goal_time_window (10 steps), goal_speed_margin (5 m/s),
    goal_velocity (True; False = the CLI's --no-goal-velocity), goal_orientation_margin
    (none), country ("ZAM"), author, affiliation, source, date ("YYYY-MM-DD" or
    datetime.date), seed, max_variations (variations(): no cap unless given), map_tolerance,
    engine_seed (0: esmini's --seed for ties it leaves to chance, e.g. at junctions),
    lenient (False: a reference to what does not exist — entity, storyboard element,
    parameter, variable, road, lane — or a distribution that cannot be sampled raises
    ConversionError; True: it is issued as a ConversionWarning and the file converts anyway).

The XML is byte for byte what ``osc2cr convert`` writes for the same file and options.
Failures raise :class:`ConversionError` (with ``file``, ``line``, ``column``); warnings are
issued as :class:`ConversionWarning`.
"""

from __future__ import annotations

import inspect
import os
import tempfile
import warnings
from collections.abc import Iterator
from typing import TYPE_CHECKING, NamedTuple, Union

from . import _osc2cr
from ._errors import ConversionError, ConversionWarning
from ._simulation import STATE_COLUMNS, DriverInput, EntityState, Event, Observation, Simulation

if TYPE_CHECKING:
    import datetime

    from commonroad.planning.planning_problem import PlanningProblemSet
    from commonroad.scenario.scenario import Scenario
    from typing_extensions import TypedDict, Unpack

    class Options(TypedDict, total=False):
        """Keyword options of the osc2cr functions (see the module docstring)."""

        dt: float
        step: float
        max_time: float
        ego: str
        ego_pattern: str
        drop_ego: bool
        params: dict[str, str | int | float | bool]
        goal_length: float
        goal_width: float
        goal_time_window: int
        goal_speed_margin: float
        goal_velocity: bool
        goal_orientation_margin: float
        country: str
        author: str
        affiliation: str
        source: str
        date: str | datetime.date
        seed: int
        max_variations: int
        map_tolerance: float
        engine_seed: int
        lenient: bool


__all__ = [
    "STATE_COLUMNS",
    "ConversionError",
    "ConversionWarning",
    "DriverInput",
    "EntityState",
    "Event",
    "Observation",
    "Simulation",
    "Variation",
    "convert",
    "convert_to_xml",
    "convert_variation",
    "convert_variation_to_xml",
    "count_variations",
    "output_name",
    "read_xml",
    "variations",
    "__version__",
]

__version__: str = _osc2cr.__version__

PathLike = Union[str, "os.PathLike[str]"]


class Variation(NamedTuple):
    """One converted variation of a parameter distribution."""

    index: int
    """1-based; the ``_<index>`` of the CLI's output name and the benchmark id's config id."""
    parameters: dict[str, str]
    """The parameter values of this variation."""
    xml: str
    """The CommonRoad XML text."""


def _warn(found: list[tuple[str, str]]) -> None:
    for stage, message in found:
        warnings.warn(f"{stage}: {message}", ConversionWarning, stacklevel=3)


def convert_to_xml(path: PathLike, **options: Unpack[Options]) -> str:
    """Converts the OpenSCENARIO scenario file ``path`` into CommonRoad 2020a XML text.

    Needs no commonroad-io. Raises :class:`ConversionError` when the scenario cannot be
    converted (a parameter distribution file too: use :func:`variations`), ``TypeError`` /
    ``ValueError`` for a bad option.
    """
    xml, found = _osc2cr.convert_file(os.fspath(path), **options)
    _warn(found)
    return xml


def convert(path: PathLike, **options: Unpack[Options]) -> tuple[Scenario, PlanningProblemSet]:
    """Converts the scenario file ``path`` and reads the result with the installed
    commonroad-io (2024.x or 2026.x): returns ``(Scenario, PlanningProblemSet)``."""
    return read_xml(convert_to_xml(path, **options))


def convert_variation_to_xml(path: PathLike, index: int, **options: Unpack[Options]) -> str:
    """The XML of variation ``index`` (1-based) of the parameter distribution file ``path``,
    computed alone (random access: any worker can convert any variation)."""
    xml, found = _osc2cr.convert_variation(os.fspath(path), index, **options)
    _warn(found)
    return xml


def convert_variation(
    path: PathLike, index: int, **options: Unpack[Options]
) -> tuple[Scenario, PlanningProblemSet]:
    """Variation ``index`` of the distribution file ``path`` as commonroad-io objects."""
    return read_xml(convert_variation_to_xml(path, index, **options))


def variations(
    path: PathLike, start: int = 1, stop: int | None = None, **options: Unpack[Options]
) -> Iterator[Variation]:
    """The variations ``start <= index < stop`` of the parameter distribution file ``path``,
    converted one at a time as the iterator is advanced (constant memory: stream as many as
    the distribution has). ``stop`` defaults to the end; ``max_variations`` caps it as in the
    CLI. A variation that fails raises :class:`ConversionError` (its ``variation`` says which);
    the distribution file itself is read, and checked, when this function is called."""
    native = _osc2cr.variations(os.fspath(path), start, stop, **options)
    return _stream(native)


def count_variations(path: PathLike, **options: Unpack[Options]) -> int:
    """How many variations :func:`variations` yields for these options (the distribution's
    parameter sets, capped by ``max_variations``); nothing is converted."""
    return len(_osc2cr.variations(os.fspath(path), 1, None, **options))


def _stream(native: _osc2cr.Variations) -> Iterator[Variation]:
    for index, parameters, xml, found in native:
        _warn(found)
        yield Variation(index, dict(parameters), xml)


def output_name(path: PathLike, index: int | None = None) -> str:
    """The file name ``osc2cr convert path -o OUT`` gives the scenario (``<stem>.xml``) or
    its variation ``index`` (``<stem>_<index>.xml``)."""
    stem = os.path.splitext(os.path.basename(os.fspath(path)))[0] or "scenario"
    return f"{stem}.xml" if index is None else f"{stem}_{index}.xml"


def read_xml(xml: str, lanelet_assignment: bool = False) -> tuple[Scenario, PlanningProblemSet]:
    """Reads CommonRoad XML text with the installed commonroad-io, whichever reader API it
    has (2024.x: ``CommonRoadFileReader(path)``; 2026.x: ``CommonRoadFileReader(filename_2020a=path)``).
    ``lanelet_assignment``: commonroad-io assigns every obstacle state to its lanelets (what
    e.g. commonroad-crime's measures need)."""
    try:
        from commonroad.common.file_reader import CommonRoadFileReader
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "osc2cr.convert needs commonroad-io (pip install commonroad-io); "
            "osc2cr.convert_to_xml works without it"
        ) from e
    fd, tmp = tempfile.mkstemp(suffix=".xml", prefix="osc2cr-")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(xml)
        if "filename_2020a" in inspect.signature(CommonRoadFileReader.__init__).parameters:
            reader = CommonRoadFileReader(filename_2020a=tmp)
        else:
            reader = CommonRoadFileReader(tmp)
        return reader.open(lanelet_assignment=lanelet_assignment)
    finally:
        os.unlink(tmp)
