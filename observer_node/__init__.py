"""chest-observer: real-time chest acceleration (CR) and deflection (CD) observer for crash
benches, after Blåberg (2008), "Chest Observer for Crash Safety Enhancement"."""

__version__ = "0.2.0"
