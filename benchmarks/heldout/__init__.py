"""Independent held-out crash tests: a thorax/belt/retractor simulator written from the physics
(not from the observer's effect library), an ISO-MME writer and the held-out cases."""
