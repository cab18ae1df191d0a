"""osc2cr: OpenSCENARIO (+ OpenDRIVE) to CommonRoad, natively (Rust), in milliseconds.

    import osc2cr
    scenario, problems = osc2cr.convert("cut_in.xosc", dt=0.1)   # commonroad-io objects
    xml = osc2cr.convert_to_xml("cut_in.xosc")                  # CommonRoad 2020a XML text
    files = osc2cr.convert_to_protobuf("cut_in.xosc")           # the 2024 format's three files
    for v in osc2cr.variations("cut-in_parameter_set.xosc"):    # lazy: one at a time
        print(v.index, v.parameters, len(v.xml))
    osc2cr.export("USA_US101-4_1_T-1.xml", "out/")              # the way back: .xosc + .xodr
    osc2cr.export(scenario, "out/", problems)                   # a commonroad-io Scenario too

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
    ConversionError; True: it is issued as a ConversionWarning and the file converts anyway),
    format ("2020a": one XML text; "2024": the 2024 format's map, scenario and dynamic files,
    see :class:`Protobuf2024`).

The XML, and the 2024 files, are byte for byte what ``osc2cr convert`` writes for the same file
and options. With ``format="2024"``, :func:`convert` and :func:`convert_variation` read the
three files with commonroad-io's three-file reader (commonroad-io 2026.x), :func:`variations`
yields them as ``Variation.protobuf``, and :func:`convert_to_xml` refuses (use
:func:`convert_to_protobuf`). Failures raise :class:`ConversionError` (with ``file``, ``line``,
``column``) — for a scenario file that does not exist :class:`ScenarioNotFoundError`, which is
also a ``FileNotFoundError``; warnings are issued as :class:`ConversionWarning`. Messages name
options as these keywords (``lenient=True``, ``params``), not as the command line's.
"""

from __future__ import annotations

import inspect
import os
import tempfile
import warnings
from collections.abc import Iterator
from typing import TYPE_CHECKING, NamedTuple, Optional, Union

from . import _osc2cr
from ._errors import ConversionError, ConversionWarning, ScenarioNotFoundError
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
        format: str


__all__ = [
    "STATE_COLUMNS",
    "ConversionError",
    "ScenarioNotFoundError",
    "ConversionWarning",
    "DriverInput",
    "EntityState",
    "Event",
    "Observation",
    "Protobuf2024",
    "Simulation",
    "Variation",
    "convert",
    "convert_to_protobuf",
    "convert_to_xml",
    "convert_variation",
    "convert_variation_to_protobuf",
    "convert_variation_to_xml",
    "count_variations",
    "export",
    "Exported",
    "output_name",
    "read_protobuf",
    "read_protobuf_files",
    "read_xml",
    "variations",
    "__version__",
]

__version__: str = _osc2cr.__version__

PathLike = Union[str, "os.PathLike[str]"]


class Protobuf2024(NamedTuple):
    """A scenario in the CommonRoad 2024 format: three protobuf files, as bytes."""

    map_id: str
    """The map's id, ``COUNTRY_<hash of its content>-1``: the scenario file refers to the map by
    it, and the map's file is ``<map_id>.pb``. Scenarios on the same lanelet network share it."""
    map: bytes
    """The map file (``CommonRoadMap``)."""
    scenario: bytes
    """The scenario file (``CommonRoadScenario``: meta information, planning problems)."""
    dynamic: bytes
    """The dynamic file (``CommonRoadDynamic``: obstacles, traffic-light cycles)."""

    def write(self, folder: PathLike, name: str) -> tuple[str, str, str]:
        """Writes ``<folder>/<name>-SC.pb``, ``<folder>/<name>.pb`` and, if it is not there yet,
        ``<folder>/<map_id>.pb`` — the names ``osc2cr convert --format 2024`` gives them —
        each whole or not at all; returns their paths (scenario, dynamic, map)."""
        folder = os.fspath(folder)
        paths = (
            os.path.join(folder, f"{name}-SC.pb"),
            os.path.join(folder, f"{name}.pb"),
            os.path.join(folder, f"{self.map_id}.pb"),
        )
        if not os.path.exists(paths[2]):
            _write_whole(paths[2], self.map)
        _write_whole(paths[1], self.dynamic)
        _write_whole(paths[0], self.scenario)
        return paths


def _write_whole(path: str, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path) or ".", prefix=".osc2cr-", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


class Exported(NamedTuple):
    """What :func:`export` wrote."""

    xosc: str
    """The OpenSCENARIO file, ``<out_dir>/<name>.xosc``."""
    xodr: Optional[str]
    """The OpenDRIVE file of its lanelet network, ``<out_dir>/<COUNTRY>_<hash>.xodr`` (named by its
    content, shared by every scenario on the same network); None when the network has no lanelet."""
    warnings: list[str]
    """What the OpenSCENARIO file says approximately or not at all (also issued as warnings)."""


class Variation(NamedTuple):
    """One converted variation of a parameter distribution."""

    index: int
    """1-based; the ``_<index>`` of the CLI's output name and the benchmark id's config id."""
    parameters: dict[str, str]
    """The parameter values of this variation."""
    xml: Optional[str]
    """The CommonRoad 2020a XML text (None with ``format="2024"``)."""
    protobuf: Optional[Protobuf2024] = None
    """The 2024 files (with ``format="2024"``; None otherwise)."""


def export(
    scenario_or_path: Union[PathLike, Scenario],
    out_dir: PathLike,
    planning_problems: Optional[PlanningProblemSet] = None,
    *,
    osc: str = "1.3",
    ego_controller: str = "default",
    play_to_end: bool = False,
    name: Optional[str] = None,
) -> Exported:
    """Exports a CommonRoad scenario as OpenSCENARIO + OpenDRIVE into ``out_dir``, as
    ``osc2cr export FILE -o OUT_DIR`` does (the way back of :func:`convert`).

    ``scenario_or_path`` is a CommonRoad file (2018b or 2020a XML, or a 2024 scenario file
    ``NAME-SC.pb`` with its dynamic file and map beside it) or a commonroad-io ``Scenario``, with
    its ``PlanningProblemSet`` as ``planning_problems`` (each planning problem becomes an ego);
    a ``Scenario`` is written to 2020a XML with commonroad-io's own writer first (10 decimals),
    named ``name`` (default: its scenario id). ``osc``: "1.3", or "1.0" for simulators that read
    only 1.0; ``ego_controller``: "default" (the ego keeps its lane and speed) or "external" (an
    outside driver, esmini's ExternalController); ``play_to_end``: reaching the goal does not end
    the run. Raises :class:`ConversionError` when nothing could be written, ``ValueError`` for a
    bad option; warnings are issued as :class:`ConversionWarning`.
    """
    out_dir = os.fspath(out_dir)
    if isinstance(scenario_or_path, (str, os.PathLike)):
        if planning_problems is not None:
            raise TypeError("planning_problems goes with a commonroad-io Scenario; a file holds its own")
        xosc, xodr, found = _osc2cr.export_file(os.fspath(scenario_or_path), out_dir, osc, ego_controller, play_to_end)
    else:
        stem = name or "".join(c for c in str(scenario_or_path.scenario_id) if c.isalnum() or c in "-_") or "scenario"
        with tempfile.TemporaryDirectory(prefix="osc2cr-export-") as tmp:
            path = os.path.join(tmp, f"{stem}.xml")
            _write_2020a(scenario_or_path, planning_problems, path)
            xosc, xodr, found = _osc2cr.export_file(path, out_dir, osc, ego_controller, play_to_end)
    for w in found:
        warnings.warn(w, ConversionWarning, stacklevel=2)
    return Exported(os.fspath(xosc), None if xodr is None else os.fspath(xodr), list(found))


def _write_2020a(scenario: Scenario, problems: Optional[PlanningProblemSet], path: str) -> None:
    """Writes a commonroad-io scenario as 2020a XML with commonroad-io's writer, 10 decimals:
    2024.x (author and the like on the scenario) and 2026.x (on its ``file_information``, the
    lanelet network's ``location``, protobuf unless XML is asked for)."""
    try:
        from commonroad.common.file_writer import CommonRoadFileWriter, OverwriteExistingFile
        from commonroad.planning.planning_problem import PlanningProblemSet as _Set
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("exporting a commonroad-io Scenario needs commonroad-io (pip install commonroad-io)") from e
    init = inspect.signature(CommonRoadFileWriter.__init__).parameters
    info = getattr(scenario, "file_information", None) or scenario

    def said(name: str) -> str:
        return getattr(info, name, None) or ""

    options = {
        "author": said("author") or "osc2cr",
        "affiliation": said("affiliation"),
        "source": said("source"),
        "tags": set(getattr(scenario, "tags", None) or ()),
    }
    if "decimal_precision" in init:
        options["decimal_precision"] = 10
    if "file_format" in init:
        from commonroad.common.util import FileFormat

        options["file_format"] = FileFormat.XML
    if "location" in init:
        location = getattr(scenario, "location", None) or getattr(scenario.lanelet_network, "location", None)
        if location is not None:
            options["location"] = location
    writer = CommonRoadFileWriter(scenario, problems if problems is not None else _Set(), **options)
    write = inspect.signature(writer.write_to_file).parameters
    if "filename_2020a" in write:
        writer.write_to_file(filename_2020a=path, overwrite_existing_file=OverwriteExistingFile.ALWAYS)
    else:
        writer.write_to_file(path, OverwriteExistingFile.ALWAYS)


def _warn(found: list[tuple[str, str]]) -> None:
    for stage, message in found:
        warnings.warn(f"{stage}: {message}", ConversionWarning, stacklevel=3)


def _is_2024(options: dict) -> bool:
    return options.get("format") == "2024"


def _files(payload: tuple) -> Protobuf2024:
    return Protobuf2024(*payload[1])


def convert_to_xml(path: PathLike, **options: Unpack[Options]) -> str:
    """Converts the OpenSCENARIO scenario file ``path`` into CommonRoad 2020a XML text.

    Needs no commonroad-io. Raises :class:`ConversionError` when the scenario cannot be
    converted (a parameter distribution file too: use :func:`variations`), ``TypeError`` /
    ``ValueError`` for a bad option (``format="2024"`` too: use :func:`convert_to_protobuf`).
    """
    if _is_2024(options):
        raise ValueError("convert_to_xml writes the 2020a format; use convert_to_protobuf for format='2024'")
    payload, found = _osc2cr.convert_file(os.fspath(path), **options)
    _warn(found)
    return payload[0]


def convert_to_protobuf(path: PathLike, **options: Unpack[Options]) -> Protobuf2024:
    """Converts the OpenSCENARIO scenario file ``path`` into the CommonRoad 2024 format: the
    map, scenario and dynamic files as bytes (needs no commonroad-io)."""
    options["format"] = "2024"
    payload, found = _osc2cr.convert_file(os.fspath(path), **options)
    _warn(found)
    return _files(payload)


def convert(path: PathLike, **options: Unpack[Options]) -> tuple[Scenario, PlanningProblemSet]:
    """Converts the scenario file ``path`` and reads the result with the installed
    commonroad-io: returns ``(Scenario, PlanningProblemSet)``. 2020a (the default): any
    commonroad-io 2024.x or 2026.x; ``format="2024"``: read with the three-file reader of
    commonroad-io 2026.x."""
    if _is_2024(options):
        return read_protobuf(convert_to_protobuf(path, **options))
    return read_xml(convert_to_xml(path, **options))


def convert_variation_to_xml(path: PathLike, index: int, **options: Unpack[Options]) -> str:
    """The XML of variation ``index`` (1-based) of the parameter distribution file ``path``,
    computed alone (random access: any worker can convert any variation)."""
    if _is_2024(options):
        raise ValueError("convert_variation_to_xml writes the 2020a format; use convert_variation_to_protobuf")
    payload, found = _osc2cr.convert_variation(os.fspath(path), index, **options)
    _warn(found)
    return payload[0]


def convert_variation_to_protobuf(path: PathLike, index: int, **options: Unpack[Options]) -> Protobuf2024:
    """The 2024 files of variation ``index`` (1-based) of the distribution file ``path``."""
    options["format"] = "2024"
    payload, found = _osc2cr.convert_variation(os.fspath(path), index, **options)
    _warn(found)
    return _files(payload)


def convert_variation(
    path: PathLike, index: int, **options: Unpack[Options]
) -> tuple[Scenario, PlanningProblemSet]:
    """Variation ``index`` of the distribution file ``path`` as commonroad-io objects."""
    if _is_2024(options):
        return read_protobuf(convert_variation_to_protobuf(path, index, **options))
    return read_xml(convert_variation_to_xml(path, index, **options))


def variations(
    path: PathLike, start: int = 1, stop: int | None = None, **options: Unpack[Options]
) -> Iterator[Variation]:
    """The variations ``start <= index < stop`` of the parameter distribution file ``path``,
    converted one at a time as the iterator is advanced (constant memory: stream as many as
    the distribution has; the road network is read once). ``stop`` defaults to the end;
    ``max_variations`` caps it as in the CLI. A variation that fails raises
    :class:`ConversionError` (its ``variation`` says which); the distribution file itself is
    read, and checked, when this function is called. With ``format="2024"`` each variation
    carries ``protobuf`` (its scenario and dynamic files and the shared map) instead of ``xml``."""
    native = _osc2cr.variations(os.fspath(path), start, stop, **options)
    return _stream(native)


def count_variations(path: PathLike, **options: Unpack[Options]) -> int:
    """How many variations :func:`variations` yields for these options (the distribution's
    parameter sets, capped by ``max_variations``); nothing is converted."""
    return len(_osc2cr.variations(os.fspath(path), 1, None, **options))


def _stream(native: _osc2cr.Variations) -> Iterator[Variation]:
    for index, parameters, payload, found in native:
        _warn(found)
        xml, files = payload
        yield Variation(index, dict(parameters), xml, None if files is None else Protobuf2024(*files))


def output_name(path: PathLike, index: int | None = None, format: str = "2020a") -> str:
    """The file name ``osc2cr convert path -o OUT`` gives the scenario (``<stem>.xml``) or its
    variation ``index`` (``<stem>_<index>.xml``); with ``format="2024"`` the scenario file's
    (``<stem>-SC.pb``; the dynamic file is ``<stem>.pb``, the map ``<map_id>.pb``)."""
    stem = os.path.splitext(os.path.basename(os.fspath(path)))[0] or "scenario"
    name = stem if index is None else f"{stem}_{index}"
    return f"{name}-SC.pb" if format == "2024" else f"{name}.xml"


def read_protobuf(files: Protobuf2024) -> tuple[Scenario, PlanningProblemSet]:
    """Reads the 2024 files with commonroad-io's three-file reader (commonroad-io 2026.x:
    ``CommonRoadFileReader(filename_map=..., filename_scenario=..., filename_dynamic=...).open_all()``)."""
    reader = _file_reader()
    if "filename_map" not in inspect.signature(reader.__init__).parameters:
        raise ImportError("reading the CommonRoad 2024 format needs commonroad-io 2026.x (its three-file reader)")
    scenario, problems, _cooperative = reader(
        filename_map=files.map, filename_scenario=files.scenario, filename_dynamic=files.dynamic
    ).open_all()
    return scenario, problems


def read_protobuf_files(scenario_file: PathLike, map_dir: PathLike | None = None) -> tuple[Scenario, PlanningProblemSet]:
    """Reads a scenario ``osc2cr convert --format 2024`` wrote: ``NAME-SC.pb``, its dynamic file
    ``NAME.pb`` beside it, and the map it names, ``<map_id>.pb``, from ``map_dir`` (default: the
    scenario's folder or the nearest folder above it that holds it — the top of the output)."""
    from commonroad.common.protobuf.scenario import commonroad_scenario_pb2

    scenario_file = os.fspath(scenario_file)
    if not scenario_file.endswith("-SC.pb"):
        raise ValueError(f"{scenario_file}: a 2024 scenario file is named NAME-SC.pb")
    with open(scenario_file, "rb") as f:
        scenario_bytes = f.read()
    message = commonroad_scenario_pb2.CommonRoadScenario()
    message.ParseFromString(scenario_bytes)
    map_name = f"{message.map_id}.pb"
    if map_dir is not None:
        map_path = os.path.join(os.fspath(map_dir), map_name)
    else:
        folder = os.path.dirname(os.path.abspath(scenario_file))
        map_path = os.path.join(folder, map_name)
        while not os.path.exists(map_path) and os.path.dirname(folder) != folder:
            folder = os.path.dirname(folder)
            map_path = os.path.join(folder, map_name)
    with open(map_path, "rb") as f:
        map_bytes = f.read()
    with open(scenario_file[: -len("-SC.pb")] + ".pb", "rb") as f:
        dynamic_bytes = f.read()
    return read_protobuf(Protobuf2024(message.map_id, map_bytes, scenario_bytes, dynamic_bytes))


def _file_reader():
    try:
        from commonroad.common.file_reader import CommonRoadFileReader
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "osc2cr.convert needs commonroad-io (pip install commonroad-io); "
            "osc2cr.convert_to_xml and convert_to_protobuf work without it"
        ) from e
    return CommonRoadFileReader


def read_xml(xml: str, lanelet_assignment: bool = False) -> tuple[Scenario, PlanningProblemSet]:
    """Reads CommonRoad XML text with the installed commonroad-io, whichever reader API it
    has (2024.x: ``CommonRoadFileReader(path)``; 2026.x: ``CommonRoadFileReader(filename_2020a=path)``).
    ``lanelet_assignment``: commonroad-io assigns every obstacle state to its lanelets (what
    e.g. commonroad-crime's measures need)."""
    reader = _file_reader()
    fd, tmp = tempfile.mkstemp(suffix=".xml", prefix="osc2cr-")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(xml)
        if "filename_2020a" in inspect.signature(reader.__init__).parameters:
            return reader(filename_2020a=tmp).open(lanelet_assignment=lanelet_assignment)
        return reader(tmp).open(lanelet_assignment=lanelet_assignment)
    finally:
        os.unlink(tmp)
