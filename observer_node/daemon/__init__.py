"""The real-time daemon: config, bus ports, inputs -> per-tick core -> outputs, the tick
loop (node.py) that also keeps the recording process (observer_node.recording) alive."""
