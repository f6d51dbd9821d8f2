import sys

from .entry import observer_node

sys.exit(observer_node())
