"""Stand-in for rps.utilities: barrier_certificates, controllers, transformations, graph and misc,
each DREAM's own (python/dream/), loaded by _dream_toolbox."""
