"""sillage: guaranteed state estimation by constraint programming over intervals and tubes."""
from ._sillage import *  # noqa: F401,F403
from ._sillage import Error  # noqa: F401
