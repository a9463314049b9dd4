"""Stand-in for rps.utilities (only what DREAM's exported scripts use)."""
