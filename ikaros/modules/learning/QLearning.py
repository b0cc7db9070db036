"""QLearning: tabular Q-learning with four actions."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class QLearning(Module):
    """Tabular Q-learning with four actions over a one-hot STATE of any shape (typically the
    LOCATION map of a GridWorld; the state is the position of the largest element). Every Q
    value starts at ``initial``. On each tick, from tick 1 on, the value of the action taken on
    the previous tick in the previous state is moved toward a target: Q += alpha * (target -
    Q). With horizon ``infinite`` the target is gamma * (r + max_a Q(s, a)), r being the first
    element of REINFORCEMENT and s the current state; a positive r marks a goal and the
    target is then gamma * r (the episode ends there: GridWorld moves the agent back to its
    start). With ``finite`` the target is gamma * r for a positive r and gamma * max_a Q(s, a)
    otherwise (negative reinforcement is not learned). The new action is,
    with probability ``epsilon``, a random one; otherwise the action with the largest Q value
    in the current state (the first on ties), or a random one while all of them are 0. ACTION
    is that action as a one-hot vector of four elements (for GridWorld: up, right, down,
    left). VALUE holds max(0, max_a Q) for every state. The same ``seed`` gives the same
    run. The class is not in Ikaros 3. The golden files check Ikaros 2's values with the
    defaults (infinite horizon, no exploration, values above 0 from the start); the finite
    horizon and the random choices (epsilon, all values 0) follow the catalogue's summary
    and are this project's reading, its random numbers drawn from NumPy's generator rather
    than the original's."""

    horizon = Parameter("infinite", "infinite: reinforcement adds to the discounted value of "
                        "the next state; finite: only a positive reinforcement (a goal) counts",
                        options="infinite/finite")
    alpha = Parameter(0.1, "the learning rate", range=(0, 1))
    gamma = Parameter(0.9, "the discount factor", range=(0, 1))
    epsilon = Parameter(0.0, "the probability of choosing a random action", range=(0, 1))
    initial = Parameter(0.1, "the initial Q value of every state and action; a positive value "
                        "makes the agent explore actions it has not tried")
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives a different run "
                     "every time", type="int")
    STATE = Input("the current state, one-hot (its largest element is the state)")
    REINFORCEMENT = Input("the reinforcement received on arriving in STATE (its first element)")
    ACTION = Output("the selected action, one-hot over four actions", size="4")
    VALUE = Output("the value max(0, max_a Q) of every state", size_set="STATE")

    def init(self):
        n = self.STATE.size
        self._rng = np.random.default_rng(self.seed or None)
        self.q = np.full((4, n), self.initial, np.float32)     # Q[action, state]
        self._value = self.VALUE.reshape(-1)
        self._last_action = -1
        self._last_state = 0
        np.maximum(self.q.max(axis=0), 0, out=self._value)
        self.ACTION[...] = 0

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self.q.fill(self.initial)
            self._last_action = -1
            np.maximum(self.q.max(axis=0), 0, out=self._value)

    def tick(self):
        state = int(np.argmax(self.STATE))
        q_here = self.q[:, state]
        if self._last_action >= 0:
            r = float(self.REINFORCEMENT.flat[0]) if self.REINFORCEMENT.size else 0.0
            v = float(q_here.max())
            if self.horizon == "infinite":
                v += r
            if r > 0:
                v = r
            a, s = self._last_action, self._last_state
            self.q[a, s] += np.float32(self.alpha * (self.gamma * v - self.q[a, s]))
            self._value[s] = max(0.0, float(self.q[:, s].max()))

        action = int(self._rng.integers(4))
        if self._rng.random() >= self.epsilon and np.any(q_here != 0):
            action = int(np.argmax(q_here))
        self.ACTION[...] = 0
        self.ACTION[action] = 1
        self._last_action, self._last_state = action, state
