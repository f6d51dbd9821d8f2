"""The daemon's real-time hygiene, from :mod:`observer_node.realtime`, where crash-replay
finds it too without importing the daemon."""

from ..realtime import PM_QOS_DEVICE, hold_cpu_latency, restore_scheduling, set_rt_priority

__all__ = ["PM_QOS_DEVICE", "hold_cpu_latency", "restore_scheduling", "set_rt_priority"]
