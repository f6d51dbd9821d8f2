"""The real-time daemon: bus ports, the per-tick core, MCAP recording, the loop."""
