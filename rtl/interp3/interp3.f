// rtl/interp3: the 3-axis linear core of paper B's second stage.
interp3/interp3_core.v
