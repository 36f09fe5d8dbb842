# host_sim: the simulated AM1808 and EV3 devices (host configurations only;
# nothing here goes into the AM1808 target library).
#   include/host_sim/          core API: regs, board, gpio, intc, psc, syscfg, clock, trace, scenario
#   include/host_sim/devices/  device models (eHRPWM/eCAP, SPI0 + ADC, UARTs, motors, sensors)
#   src/                       core: register space, trapping, AINTC, GPIO, PSC, SYSCFG, TIMER64P3, traces
#   src/devices/               device models
HOST_SRCS += $(sort $(wildcard host_sim/src/*.c) $(wildcard host_sim/src/devices/*.c))
