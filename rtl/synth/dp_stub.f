// The timing stub of the analysis design core_nodp (designs.mk), alone: its lint run.
synth/dp_stub.v
