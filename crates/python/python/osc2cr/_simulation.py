"""Closed loop: an OpenSCENARIO scenario stepped from Python while a planner drives some of
its entities (:class:`Simulation`), observed as commonroad-io objects (:class:`Observation`)
or as plain arrays (:meth:`Simulation.states_array`, :meth:`Simulation.step_array`).

Conventions (the same in every method):

* Time: one :meth:`Simulation.step` is one CommonRoad time step ``dt`` (0.1 s by default),
  that is ``dt / step`` engine steps (10 of 0.01 s). Driver input, hold and dead reckoning are
  held over them; a state is where the entity is at the end of the time step, the engine steps
  in between getting poses interpolated from where it was (a cubic Hermite curve through both
  positions with both velocity vectors; heading the short way round and speed linearly).
  ``dt = step`` steps the engine itself.
* Positions are CommonRoad positions: the centre of the entity's bounding box (the
  OpenSCENARIO reference point, e.g. a car's rear axle, moved by the box centre), in the map's
  frame, as in the CommonRoad output. Headings (rad) are counter-clockwise from x; states
  report them wrapped to (-pi, pi]. Speeds are signed, m/s, along the heading.
* An input per external entity and step, by entity name: a state (an :class:`EntityState`, a
  commonroad-io state with ``position``, ``orientation``, ``velocity`` and optionally
  ``yaw_rate``, a dict ``{"x", "y", "heading", "speed"}`` — ``position``, ``orientation``,
  ``velocity`` also accepted — with optional ``z``, ``pitch``, ``roll``, ``yaw_rate``, or a
  tuple ``(x, y, heading, speed[, z, pitch, roll, yaw_rate])``); driver input for esmini's
  vehicle model (a :class:`DriverInput` or a dict ``{"throttle", "brake", "steering"}``:
  pedals 0..1, steering -pi/2..pi/2 rad); ``"hold"`` (or None: stay where it is); or
  ``"dead_reckon"`` (go on at the last state's speed and heading).
"""

from __future__ import annotations

import math
import os
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NamedTuple, Union

from . import _osc2cr
from ._errors import ConversionWarning

if TYPE_CHECKING:
    import numpy as np
    from commonroad.planning.planning_problem import PlanningProblem, PlanningProblemSet
    from commonroad.scenario.lanelet import LaneletNetwork
    from commonroad.scenario.obstacle import DynamicObstacle, EnvironmentObstacle, StaticObstacle
    from commonroad.scenario.scenario import Scenario
    from commonroad.scenario.state import InitialState

__all__ = ["DriverInput", "EntityState", "Event", "Observation", "Simulation", "STATE_COLUMNS"]

STATE_COLUMNS: tuple[str, ...] = ("x", "y", "heading", "speed", "acceleration", "yaw_rate", "z", "present")
"""The columns of :meth:`Simulation.states_array`."""
assert len(STATE_COLUMNS) == _osc2cr.STATE_COLUMNS

#: numpy's float64 dtype name (compared with an array's dtype without importing numpy)
_FLOAT64 = "float64"

#: Stages whose warnings a simulation issues when it starts (not again with its conversion).
_LOAD_STAGES = ("load", "road_network", "map")


class EntityState(NamedTuple):
    """A state to put an external entity in (CommonRoad position: the box centre)."""

    x: float
    y: float
    heading: float
    """rad"""
    speed: float
    """m/s, signed along the heading"""
    z: float | None = None
    """height of the reference point; None: on the road surface"""
    pitch: float | None = None
    """rad; None: the road's"""
    roll: float | None = None
    """rad; None: the road's"""
    yaw_rate: float | None = None
    """rad/s; None: derived from the heading change"""


class DriverInput(NamedTuple):
    """Pedals and steering for esmini's vehicle model of an external entity."""

    throttle: float = 0.0
    """0..1"""
    brake: float = 0.0
    """0..1"""
    steering: float = 0.0
    """rad, -pi/2..pi/2: the wheels turn towards it (esmini's model; less at speed)"""


class Event(NamedTuple):
    """A storyboard element changed state (esmini's event log)."""

    time: float
    element: str
    from_state: str
    transition: str
    """e.g. ``start``, ``end``, ``stop``"""
    to_state: str


@dataclass(frozen=True)
class Observation:
    """What the run looks like at one CommonRoad time step, as commonroad-io objects.

    The lanelet network, the static and environment obstacles and the planning problem are
    the same objects in every observation of a simulation (built once)."""

    time: float
    """s"""
    time_step: int
    """CommonRoad time step (time / dt)"""
    ego: InitialState | None
    """the ego's state now (None while it does not exist)"""
    obstacles: list[DynamicObstacle]
    """the other road users that exist now, each a DynamicObstacle with its CommonRoad id,
    type and shape as the conversion gives them and its current state as initial state (no
    prediction)"""
    lanelet_network: LaneletNetwork
    planning_problem: PlanningProblem
    """the ego's planning problem of the open-loop conversion: it starts where the ego starts,
    and its goal is where and when the scenario's own script brings the ego (a box around its
    final position, the last time steps, its final speed ± a margin: the ``goal_*`` options)"""
    static_obstacles: list[StaticObstacle] = field(default_factory=list)
    environment_obstacles: list[EnvironmentObstacle] = field(default_factory=list)
    external: dict[str, InitialState] = field(default_factory=dict)
    """the state now of every entity driven from outside that exists, by name (the ego too)"""


InputLike = Union[None, str, EntityState, DriverInput, Mapping, Sequence, Any]


def _number(name: str, what: str, value: Any) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        raise TypeError(f"input for `{name}`: {what} must be a number, got {value!r}") from None


def _optional(name: str, what: str, value: Any) -> float | None:
    return None if value is None else _number(name, what, value)


def _first(m: Mapping, *keys: str) -> Any:
    for k in keys:
        if k in m:
            return m[k]
    return None


def _state_parts(name: str, x, y, heading, speed, z=None, pitch=None, roll=None, yaw_rate=None) -> tuple[str, str, list]:
    for what, v in (("x", x), ("y", y), ("heading", heading), ("speed", speed)):
        if v is None:
            raise TypeError(f"input for `{name}`: a state needs x, y, heading and speed; {what} is missing")
    return (
        name,
        "state",
        [_number(name, "x", x), _number(name, "y", y), _number(name, "heading", heading), _number(name, "speed", speed),
         _optional(name, "z", z), _optional(name, "pitch", pitch), _optional(name, "roll", roll),
         _optional(name, "yaw_rate", yaw_rate)],
    )


def _native_input(name: str, value: InputLike) -> tuple[str, str, list]:
    """One input in any accepted form → (name, kind, numbers) for the native session."""
    if value is None:
        return (name, "hold", [])
    if isinstance(value, str):
        if value in ("hold", "dead_reckon"):
            return (name, value, [])
        raise ValueError(f"input for `{name}`: {value!r} is not an input (a state, DriverInput, \"hold\" or \"dead_reckon\")")
    if isinstance(value, DriverInput):
        return (name, "driver", [_number(name, k, getattr(value, k)) for k in ("throttle", "brake", "steering")])
    if isinstance(value, EntityState):
        return _state_parts(name, *value)
    if isinstance(value, Mapping):
        if any(k in value for k in ("throttle", "brake", "steering")):
            return (name, "driver", [_number(name, k, value.get(k, 0.0)) for k in ("throttle", "brake", "steering")])
        position = value.get("position")
        x, y = (position[0], position[1]) if position is not None else (value.get("x"), value.get("y"))
        return _state_parts(name, x, y, _first(value, "heading", "orientation"), _first(value, "speed", "velocity"),
                            value.get("z"), value.get("pitch"), value.get("roll"), value.get("yaw_rate"))
    if hasattr(value, "position") and hasattr(value, "orientation"):
        # a commonroad-io state
        position = value.position
        speed = getattr(value, "velocity", None)
        vy = getattr(value, "velocity_y", None)
        if vy is not None and speed is not None:  # a point-mass state: velocity is its x part
            speed = math.hypot(float(speed), float(vy))
        return _state_parts(name, position[0], position[1], value.orientation, speed,
                            yaw_rate=getattr(value, "yaw_rate", None))
    if isinstance(value, Sequence) and 4 <= len(value) <= 8:
        return _state_parts(name, *value)
    raise TypeError(
        f"input for `{name}`: {type(value).__name__} is not an input; give a state (EntityState, a commonroad-io "
        "state, a dict or a tuple x, y, heading, speed), DriverInput, \"hold\" or \"dead_reckon\""
    )


def _warn(found, skip=()) -> None:
    for stage, message in found:
        if stage not in skip:
            warnings.warn(f"{stage}: {message}", ConversionWarning, stacklevel=3)


class _OpenLoop:
    """What every observation shares, from the open-loop conversion (computed once): the ego,
    the obstacle ids; read with commonroad-io when first asked for, the lanelet network, the
    planning problem, the fixed obstacles and each road user's type and shape."""

    def __init__(self, native: _osc2cr.Session) -> None:
        xml, _warnings, names, ego = native.open_loop()
        self.xml: str = xml
        self.ego: str = ego
        # each entity's first obstacle (an entity that disappears and comes back is several)
        self.ids: dict[str, int] = {}
        for oid, entity in names:
            self.ids.setdefault(entity, oid)
        self._read = False

    def read(self) -> _OpenLoop:
        if self._read:
            return self
        from . import read_xml

        scenario, problems = read_xml(self.xml)
        self.lanelet_network = scenario.lanelet_network
        self.planning_problem = next(iter(sorted(problems.planning_problem_dict.items())))[1]
        self.static_obstacles = list(scenario.static_obstacles)
        self.environment_obstacles = list(getattr(scenario, "environment_obstacle", []) or [])
        dynamic = {o.obstacle_id: o for o in scenario.dynamic_obstacles}
        self.templates = {
            entity: (oid, dynamic[oid].obstacle_type, dynamic[oid].obstacle_shape)
            for entity, oid in self.ids.items()
            if oid in dynamic
        }
        self._read = True
        return self


class Simulation:
    """An OpenSCENARIO scenario run in closed loop: the engine runs the storyboard and every
    other road user while the caller drives the external entities, step by step; the
    storyboard's conditions and the driver models react to where they are. At any point
    :meth:`to_commonroad` is the run so far as the CommonRoad scenario ``osc2cr convert``
    would write had the scenario gone this way.

    ``external``: which entities the caller drives — None (default): those whose controller
    needs an outside driver (esmini's ExternalController, InteractiveController,
    UDPDriverController, ExternalDriverModel), each from when its controller is activated
    (until then the engine drives it); a list of entity names: those, from the first step.
    ``motion``: what the storyboard's motion actions do to an external entity —
    ``"overridden"`` (default, esmini's rule for an entity whose controller overrides them:
    speed actions end at once, lane changes, trajectories, … run without moving it, the
    storyboard follows the course the caller's driving gives it) or ``"replaced"`` (the
    engine moves it as scripted and the caller's input replaces the result each step: the
    storyboard keeps the author's timing, while every condition and driver model sees the
    entity where the caller put it). ``observe_every``: :meth:`step` returns an observation
    every N-th time step (and at the end), None otherwise. Other keyword options are those
    of :func:`osc2cr.convert` (``dt``, ``step``, ``max_time``, ``params``, ``ego``,
    ``lenient``, ...); ``dt`` must be a whole multiple of ``step``.

    The ego (of observations and of :meth:`to_commonroad`) is the first external entity, or
    the ``ego`` option's. Loading warnings are issued when the simulation starts, the run's
    with :meth:`to_xml`, as :class:`ConversionWarning`; a file that cannot be converted
    raises :class:`ConversionError`, a wrong argument ``ValueError``/``TypeError``.
    """

    def __init__(
        self,
        path: str | os.PathLike[str],
        external: Sequence[str] | str | None = None,
        *,
        motion: str = "overridden",
        observe_every: int = 1,
        **options: Any,
    ) -> None:
        if isinstance(observe_every, bool) or not isinstance(observe_every, int) or observe_every < 1:
            raise ValueError(f"observe_every must be an int >= 1, got {observe_every!r}")
        self._path = os.fspath(path)
        self._external = None if external is None else ([external] if isinstance(external, str) else list(external))
        self._motion = motion
        self._options = options
        self._observe_every = observe_every
        self._open: _OpenLoop | None = None
        self._native: _osc2cr.Session | None = None
        self._view: np.ndarray | None = None
        self._buffer = bytearray()
        self._start()
        self._fresh = True

    def _start(self) -> None:
        self._native = _osc2cr.Session(self._path, self._external, self._motion, **self._options)
        self._events: list[Event] = []
        self._fresh = True
        _warn(self._native.load_warnings())

    @property
    def _session(self) -> _osc2cr.Session:
        if self._native is None:
            raise RuntimeError("the simulation is closed")
        return self._native

    # --- the run ---------------------------------------------------------------------------

    def reset(self) -> Observation:
        """Starts the run again (the scenario is loaded anew; the first reset after creating
        the simulation uses the run it started) and returns the observation at time 0."""
        if not self._fresh:
            self._start()
        self._fresh = False
        return self.observe()

    def step(self, inputs: Mapping[str, InputLike] | None = None) -> Observation | None:
        """Advances one CommonRoad time step with an input for every entity driven from
        outside now (by name; see the module docstring for the forms); the last step of a run
        ends early if the storyboard's stop trigger fires within it. Returns the observation
        after it when one is due (every ``observe_every``-th time step, and when the run ends),
        else None. A wrong input raises ``ValueError``/``TypeError`` naming it, and the step
        is not run; stepping a run that is over raises ``RuntimeError``."""
        self.advance(inputs)
        if self._session.is_over or self.time_step % self._observe_every == 0:
            return self.observe()
        return None

    def advance(self, inputs: Mapping[str, InputLike] | None = None) -> bool:
        """:meth:`step` without an observation (nothing of commonroad-io is built): returns
        False once the run is over."""
        session = self._session
        if session.is_over:
            raise RuntimeError("the run is over (done): reset() starts it again")
        parts = [_native_input(name, value) for name, value in (inputs or {}).items()]
        self._fresh = False
        return session.step(parts)

    @property
    def done(self) -> bool:
        """The storyboard's stop trigger fired or the time cap (``max_time``) was reached."""
        return self._session.is_over

    @property
    def time(self) -> float:
        """Simulated time, s (to the nanosecond: the engine's sum of steps)."""
        return round(self._session.time, 9)

    @property
    def time_step(self) -> int:
        """The CommonRoad time step of the current time (the last one at or before it: the
        run's last step ends where the stop trigger fires, which may be between two)."""
        return math.floor(self._session.time / self._session.dt + 1e-6)

    @property
    def dt(self) -> float:
        """CommonRoad time step, s (one :meth:`step`)."""
        return self._session.dt

    @property
    def entity_names(self) -> list[str]:
        """Every entity of the run, in the order of :meth:`states_array`'s rows."""
        return self._session.entity_names

    @property
    def external(self) -> list[str]:
        """The entities driven from outside now (they need an input every step), in the
        order of :meth:`step_array`'s rows after those waiting for their controller."""
        return [name for name, _, active in self._session.external if active]

    @property
    def external_rows(self) -> list[str]:
        """The rows :meth:`step_array` takes: every entity driven from outside or waiting for
        its controller to be activated."""
        return [name for name, _, _ in self._session.external]

    @property
    def ego(self) -> str:
        """The ego entity: the one the conversion makes the ego (the first external entity
        when it moves, else the ``ego`` options' choice)."""
        return self._shared().ego

    @property
    def boxes(self) -> dict[str, tuple[float, float, float, float]]:
        """Each entity's bounding box: (centre x, centre y, length, width), the centre relative
        to the OpenSCENARIO reference point (x forward, y left)."""
        return dict(zip(self._session.entity_names, self._session.boxes))

    @property
    def obstacle_ids(self) -> dict[str, int]:
        """The CommonRoad obstacle id of each entity (as the conversion gives them; an entity
        that disappears and comes back has its first appearance's)."""
        return dict(self._shared().ids)

    @property
    def events(self) -> list[Event]:
        """The storyboard's state transitions so far."""
        self._events.extend(Event(round(t, 9), *rest) for t, *rest in self._session.events(len(self._events)))
        return list(self._events)

    def event_start(self, element: str) -> float | None:
        """When the storyboard element (an Event, Act, …) named ``element`` first started, s."""
        return next((e.time for e in self.events if e.element == element and e.transition == "start"), None)

    # --- the fast path ----------------------------------------------------------------------

    def step_array(self, values: Any, kind: str = "state") -> bool:
        """:meth:`step` with plain numbers, no observation: ``values`` holds one row per entity
        of :attr:`external_rows` (a numpy array of any shape, a flat list, or float64 bytes):
        ``kind="state"`` rows of 4 (x, y, heading, speed) or 8 (and z, pitch, roll, yaw_rate;
        NaN where not given); ``kind="driver"`` rows of 3 (throttle, brake, steering). A row
        that starts with NaN holds its entity. Returns False once the run is over."""
        if type(values) is not bytes:
            tobytes = getattr(values, "tobytes", None)
            if tobytes is not None:  # a numpy array
                values = (values if values.dtype == _FLOAT64 else values.astype(_FLOAT64)).tobytes()
        self._fresh = False
        return self._session.step_array(values, kind)

    def states_view(self) -> np.ndarray:
        """:meth:`states_array` without a copy: the same array every call, overwritten with the
        states of the time of each call (``copy()`` what you keep)."""
        session = self._session
        if self._view is None:
            import numpy as np

            self._buffer = bytearray(len(session.entity_names) * len(STATE_COLUMNS) * 8)
            self._view = np.frombuffer(self._buffer, dtype=np.float64).reshape(-1, len(STATE_COLUMNS))
        session.states_into(self._buffer)
        return self._view

    def states_array(self) -> np.ndarray:
        """Every entity's state now as a numpy array, one row per entity of
        :attr:`entity_names`, columns :data:`STATE_COLUMNS` (x, y — the box centre —,
        heading, speed, acceleration, yaw_rate, z, present: 1.0, or 0.0 with zeros while the
        entity does not exist)."""
        return self.states_view().copy()

    def osi_ground_truth(self) -> bytes:
        """The current frame as an ASAM OSI 3.5 GroundTruth message, serialized, as esmini 3.6.0
        reports it (esmini's OSI ids; box centres in the OpenDRIVE frame; the lanes and lane
        boundaries in every message): ``osi3.osi_groundtruth_pb2.GroundTruth.FromString(...)``
        reads it (``pip install osi-python``). Velocities are the change since the previous call."""
        return self._session.osi_ground_truth()

    def states_bytes(self) -> bytes:
        """:meth:`states_array` as raw float64 bytes (native byte order), without numpy."""
        return self._session.states()

    # --- observations ----------------------------------------------------------------------

    def _shared(self) -> _OpenLoop:
        if self._open is None:
            self._open = _OpenLoop(self._session)
        return self._open

    def observe(self) -> Observation:
        """The observation now (commonroad-io objects; see :class:`Observation`)."""
        import numpy as np
        from commonroad.scenario.obstacle import DynamicObstacle
        from commonroad.scenario.state import InitialState

        shared = self._shared().read()
        session = self._session
        k = self.time_step
        rows = self.states_view()
        external = {name for name, _, active in session.external if active}
        ego = None
        obstacles = []
        by_name = {}
        for name, row in zip(session.entity_names, rows.tolist()):
            x, y, heading, speed, acceleration, yaw_rate, _z, present = row
            if not present:
                continue
            state = InitialState(time_step=k, position=np.array([x, y]), orientation=heading, velocity=speed,
                                 acceleration=acceleration, yaw_rate=yaw_rate, slip_angle=0.0)
            if name in external:
                by_name[name] = state
            if name == shared.ego:
                ego = state
                continue
            template = shared.templates.get(name)
            if template is not None:
                oid, kind, shape = template
                obstacles.append(DynamicObstacle(oid, kind, shape, state))
        return Observation(
            time=self.time,
            time_step=k,
            ego=ego,
            obstacles=obstacles,
            lanelet_network=shared.lanelet_network,
            planning_problem=shared.planning_problem,
            static_obstacles=shared.static_obstacles,
            environment_obstacles=shared.environment_obstacles,
            external=by_name,
        )

    @property
    def lanelet_network(self) -> LaneletNetwork:
        """The scenario's lanelet network (commonroad-io)."""
        return self._shared().read().lanelet_network

    @property
    def planning_problem(self) -> PlanningProblem:
        """The ego's planning problem of the open-loop conversion (see :class:`Observation`)."""
        return self._shared().read().planning_problem

    # --- the run as CommonRoad --------------------------------------------------------------

    def to_xml(self) -> str:
        """The run so far as CommonRoad 2020a XML text: the bytes ``osc2cr convert`` would
        write had the scenario gone this way (the ego's trajectory the one driven; its planning
        problem's goal where the run brought it). The run's warnings are issued here."""
        xml, found, _names, _events = self._session.finish()
        _warn(found, skip=_LOAD_STAGES)
        return xml

    def to_commonroad(self, lanelet_assignment: bool = False) -> tuple[Scenario, PlanningProblemSet]:
        """:meth:`to_xml` read with commonroad-io: ``(Scenario, PlanningProblemSet)``."""
        from . import read_xml

        return read_xml(self.to_xml(), lanelet_assignment=lanelet_assignment)

    def render(self, path: str | os.PathLike[str], *, time: float | None = None, width: int = 1200,
               follow: str | None = None) -> str:
        """Draws the run so far with osc2cr's renderer (``osc2cr render``): ``.gif`` the
        whole run animated, ``.png``/``.svg`` a still at ``time`` (default: now); road users
        labelled with their entity names, the storyboard's events in the header; ``follow`` an
        entity to keep in the centre. Returns the path written."""
        path = os.fspath(path)
        ext = os.path.splitext(path)[1].lower().lstrip(".")
        if ext not in ("gif", "png", "svg"):
            raise ValueError(f"{path}: the picture must end in .gif, .png or .svg")
        data = self._session.picture(ext, time, width, follow)
        with open(path, "wb") as f:
            f.write(data)
        return path

    def rgba(self, *, time: float | None = None, width: int = 640, follow: str | None = None) -> tuple[int, int, bytes]:
        """:meth:`render`'s still as RGBA pixels: (width, height, bytes, row by row)."""
        return self._session.rgba(time, width, follow)

    def close(self) -> None:
        """Releases the run: until :meth:`reset` starts it again, nothing else can be asked."""
        self._native = None

    def __enter__(self) -> Simulation:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
