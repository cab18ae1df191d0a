"""A Gymnasium environment over :class:`osc2cr.Simulation` (``pip install osc2cr[gym]``).

The agent drives one entity of an OpenSCENARIO scenario (the ego by default) while the
engine runs the storyboard and every other road user::

    import gymnasium as gym
    import osc2cr.gym  # registers "osc2cr/Scenario-v0"

    env = gym.make("osc2cr/Scenario-v0", path="cut-in.xosc")
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())

* Observation: a ``float64`` array with one row per entity — the agent's entity first, then
  the others in the scenario's order — and the columns of :data:`osc2cr.STATE_COLUMNS` (x, y
  of the box centre, heading, speed, acceleration, yaw rate, z, present).
* Action: ``action="pedals"`` (default) two numbers in [-1, 1]: pedal (> 0 throttle, < 0
  brake) and steering (× pi/2 rad of esmini's vehicle model); ``action="state"`` the state
  at the end of the step: x, y, heading, speed (the poses in between interpolated).
* Reward: the metres the agent's entity travelled in the step, minus ``collision_penalty``
  when its bounding box overlaps another road user's; or ``reward_fn(env, info)``.
* ``terminated``: the storyboard stopped, or a collision; ``truncated``: the time cap
  (``max_time``) was reached.
* ``render_mode="rgb_array"``: the run so far drawn at the current time (osc2cr's renderer).

``reset(options={"params": {...}})`` starts the episode with other parameter values (merged
into ``params``). The scenario is deterministic: ``seed`` seeds :attr:`np_random` only.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from typing import Any

import gymnasium
import numpy as np
from gymnasium import spaces

from ._simulation import STATE_COLUMNS, DriverInput, Simulation

__all__ = ["ScenarioEnv", "boxes_overlap"]

_PRESENT = STATE_COLUMNS.index("present")


def boxes_overlap(a: tuple[float, float, float, float, float], b: tuple[float, float, float, float, float]) -> bool:
    """Whether two oriented rectangles ``(centre x, centre y, heading, length, width)``
    overlap (separating axis test)."""

    def corners(r):
        x, y, h, length, width = r
        c, s = math.cos(h), math.sin(h)
        return [(x + c * dx - s * dy, y + s * dx + c * dy)
                for dx, dy in ((length / 2, width / 2), (length / 2, -width / 2),
                               (-length / 2, -width / 2), (-length / 2, width / 2))]

    pa, pb = corners(a), corners(b)
    for h in (a[2], a[2] + math.pi / 2, b[2], b[2] + math.pi / 2):
        ux, uy = math.cos(h), math.sin(h)
        da = [px * ux + py * uy for px, py in pa]
        db = [px * ux + py * uy for px, py in pb]
        if max(da) < min(db) or max(db) < min(da):
            return False
    return True


class ScenarioEnv(gymnasium.Env):
    """One OpenSCENARIO scenario as a Gymnasium environment (see the module docstring).

    ``path``: the scenario; ``entity``: the entity the agent drives (default: the one the
    conversion makes the ego); ``action``: ``"pedals"`` or ``"state"``; other keyword options
    are :class:`osc2cr.Simulation`'s (``dt``, ``params``, ``max_time``, ``motion``, ...).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(
        self,
        path: str | os.PathLike[str],
        entity: str | None = None,
        *,
        action: str = "pedals",
        render_mode: str | None = None,
        collision_penalty: float = 100.0,
        reward_fn: Callable[[ScenarioEnv, dict[str, Any]], float] | None = None,
        render_width: int = 640,
        **options: Any,
    ) -> None:
        if action not in ("pedals", "state"):
            raise ValueError(f'action must be "pedals" or "state", got {action!r}')
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']} or None, got {render_mode!r}")
        self.path = os.fspath(path)
        self.render_mode = render_mode
        self._action = action
        self._penalty = float(collision_penalty)
        self._reward_fn = reward_fn
        self._render_width = render_width
        self._options = dict(options)
        if entity is None:
            # the entity a conversion makes the ego
            entity = Simulation(self.path, external=[], **self._options).ego
        self.entity = entity
        self.sim = self._simulation(self._options)
        names = self.sim.entity_names
        self._order = [names.index(entity)] + [i for i, n in enumerate(names) if n != entity]
        self.entity_order = [names[i] for i in self._order]
        """The entity of each observation row."""
        boxes = self.sim.boxes
        self._dims = [(boxes[n][2], boxes[n][3]) for n in self.entity_order]
        self._max_time = float(self._options.get("max_time") or 60.0)
        self.observation_space = spaces.Box(-np.inf, np.inf, shape=(len(names), len(STATE_COLUMNS)), dtype=np.float64)
        if action == "pedals":
            self.action_space = spaces.Box(-1.0, 1.0, shape=(2,), dtype=np.float32)
        else:
            self.action_space = spaces.Box(-np.inf, np.inf, shape=(4,), dtype=np.float64)

    def _simulation(self, options: dict[str, Any]) -> Simulation:
        return Simulation(self.path, external=[self.entity], **options)

    def _observation(self) -> np.ndarray:
        return np.ascontiguousarray(self.sim.states_array()[self._order])

    def _collisions(self, obs: np.ndarray) -> list[str]:
        me = obs[0]
        if not me[_PRESENT]:
            return []
        mine = (me[0], me[1], me[2], *self._dims[0])
        return [
            self.entity_order[k]
            for k in range(1, len(obs))
            if obs[k][_PRESENT] and boxes_overlap(mine, (obs[k][0], obs[k][1], obs[k][2], *self._dims[k]))
        ]

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[np.ndarray, dict[str, Any]]:
        super().reset(seed=seed)
        params = (options or {}).get("params")
        if params:
            merged = dict(self._options)
            merged["params"] = {**(self._options.get("params") or {}), **params}
            self.sim.close()
            self.sim = self._simulation(merged)
        else:
            self.sim.close()
            self.sim = self._simulation(self._options)
        obs = self._observation()
        return obs, {"time": self.sim.time, "entities": list(self.entity_order), "collision": []}

    def step(self, action: Any) -> tuple[np.ndarray, float, bool, bool, dict[str, Any]]:
        before = self.sim.states_array()[self._order[0]].copy()
        a = np.asarray(action, dtype=np.float64).reshape(-1)
        if self._action == "pedals":
            pedal, steer = float(np.clip(a[0], -1, 1)), float(np.clip(a[1], -1, 1))
            value: Any = DriverInput(throttle=max(pedal, 0.0), brake=max(-pedal, 0.0), steering=steer * math.pi / 2)
        else:
            value = (float(a[0]), float(a[1]), float(a[2]), float(a[3]))
        self.sim.advance({self.entity: value})
        obs = self._observation()
        hit = self._collisions(obs)
        info = {"time": self.sim.time, "entities": list(self.entity_order), "collision": hit}
        moved = math.hypot(obs[0][0] - before[0], obs[0][1] - before[1]) if obs[0][_PRESENT] and before[_PRESENT] else 0.0
        info["travelled"] = moved
        reward = float(self._reward_fn(self, info)) if self._reward_fn else moved - (self._penalty if hit else 0.0)
        done = self.sim.done
        truncated = bool(done and self.sim.time >= self._max_time - 0.5 * self.sim.dt)
        terminated = bool(hit) or (done and not truncated)
        return obs, reward, terminated, truncated, info

    def render(self) -> np.ndarray | None:
        if self.render_mode != "rgb_array":
            return None
        w, h, pixels = self.sim.rgba(width=self._render_width)
        return np.frombuffer(pixels, dtype=np.uint8).reshape(h, w, 4)[:, :, :3].copy()

    def close(self) -> None:
        self.sim.close()


gymnasium.register(id="osc2cr/Scenario-v0", entry_point="osc2cr.gym:ScenarioEnv")
