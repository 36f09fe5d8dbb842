# host_sim: the simulated AM1808 and EV3 devices (host configurations only;
# nothing here goes into the AM1808 target library).
#   include/host_sim/          core API: regs, board, gpio, intc, psc, syscfg, clock, trace, scenario
#   include/host_sim/devices/  device models (eHRPWM/eCAP, SPI0 + ADC, UARTs, motors, sensors)
#   src/core/                  the simulator: register space, trapping, virtual clock, traces, scenarios
#   src/soc/                   the AM1808's peripherals (AINTC, GPIO, PSC, SYSCFG, PLLC, eHRPWM/eCAP, SPI0, UARTs)
#   src/ev3/                   the EV3 board (ports, motors, sensors, LUMP, buttons/LEDs, ADC front end)
#   src/bench/                 the full-brick speed run
HOST_SRCS += $(sort $(foreach d,core soc ev3 bench,$(wildcard host_sim/src/$(d)/*.c)))
