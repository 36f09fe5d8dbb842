/*
 * app.cpp — libcpp-ev3's unit-test app, run by test_libcpp_ev3 in a bare
 * brick with large motors on A and D, touch on 1, gyro on 2, colour on 3
 * and ultrasonic on 4, the touch sensor pressed from 15 s to 16 s.  Each
 * class is driven through its public interface (its protected parts
 * through a subclass, as an app's own class would) and what it did is
 * logged as "libcpp: ..." lines, beside what EV3RT's C API says of the same
 * port, for the test to compare.
 */
#include "ev3api.h"
#include "app.h"
#include "Port.h"
#include "Motor.h"
#include "Steering.h"
#include "ColorSensor.h"
#include "GyroSensor.h"
#include "TouchSensor.h"
#include "SonarSensor.h"
#include "Clock.h"

using namespace ev3api;

/* The port enums are EV3RT's C port numbers. */
static_assert(PORT_1 == static_cast<int>(EV3_PORT_1) && PORT_4 == static_cast<int>(EV3_PORT_4),
	      "ePortS is sensor_port_t");
static_assert(PORT_A == static_cast<int>(EV3_PORT_A) && PORT_D == static_cast<int>(EV3_PORT_D),
	      "ePortM is motor_port_t");
static_assert(NUM_PORT_S == 4 && NUM_PORT_M == 4 && POWER_LOWSPEED == 2, "Port.h's constants");
static_assert(Motor::PWM_MAX == 100 && Motor::PWM_MIN == -100, "Motor's PWM range");

/* A global device object, as ET Robocon's apps have: EV3RT constructs it
 * once the platform is up, so its port is configured when main_task runs. */
static TouchSensor globalTouch(PORT_1);

/* A global pointer set by a constructor that waits for its sensor (the
 * gyro's reset), as EV3RT's samples write it: the app's tasks do not start
 * before it is set. */
static GyroSensor *globalGyro = new GyroSensor(PORT_2);

/* A Motor whose protected state the test reads, as an app's subclass can. */
class ProbeMotor : public Motor {
public:
	explicit ProbeMotor(ePortM port, bool brake = true) : Motor(port, brake) {}
	int pwm() const { return getPWM(); }
	bool brake() const { return getBrake(); }
	motor_port_t port() const { return getPort(); }
};

/* Degrees motor turns in ms after being stopped by stop(), from PWM 100. */
static int32_t coast_after_stop(ProbeMotor& motor, Clock& clock, uint32_t ms)
{
	int32_t at_stop;

	motor.setPWM(100);
	clock.sleep(600);
	motor.stop();
	at_stop = motor.getCount();
	clock.sleep(ms);
	return motor.getCount() - at_stop;
}

/* Motor: counts, offsets, clamping, brake and float, reset, destructor. */
static void test_motor(Clock& clock)
{
	ProbeMotor a(PORT_A);
	int32_t braked, coasted, before;

	syslog(LOG_NOTICE, "libcpp: motor new count %d pwm %d brake %d port %d", (int)a.getCount(), a.pwm(),
	       (int)a.brake(), (int)a.port());
	a.setPWM(50);
	clock.sleep(500);
	syslog(LOG_NOTICE, "libcpp: motor pwm %d count %d C counts %d", a.pwm(), (int)a.getCount(),
	       (int)ev3_motor_get_counts(EV3_PORT_A));
	a.setPWM(150);
	syslog(LOG_NOTICE, "libcpp: motor clamp high %d", a.pwm());
	a.setPWM(-150);
	syslog(LOG_NOTICE, "libcpp: motor clamp low %d", a.pwm());
	a.setPWM(0);
	clock.sleep(300);
	before = a.getCount();
	clock.sleep(300);
	syslog(LOG_NOTICE, "libcpp: motor pwm 0 braked moved %d C power %d", (int)(a.getCount() - before),
	       ev3_motor_get_power(EV3_PORT_A));

	a.setCount(1000);
	syslog(LOG_NOTICE, "libcpp: motor setCount 1000 reads %d, C counts %d", (int)a.getCount(),
	       (int)ev3_motor_get_counts(EV3_PORT_A));

	braked = coast_after_stop(a, clock, 400);
	a.setBrake(false);
	coasted = coast_after_stop(a, clock, 400);
	syslog(LOG_NOTICE, "libcpp: motor stop brake %d, float %d: rolled %d then %d degrees, pwm %d",
	       1, (int)a.brake(), (int)braked, (int)coasted, a.pwm());

	a.setPWM(60);
	clock.sleep(300);
	a.reset();
	clock.sleep(300);
	syslog(LOG_NOTICE, "libcpp: motor reset reads %d C counts %d pwm %d", (int)a.getCount(),
	       (int)ev3_motor_get_counts(EV3_PORT_A), a.pwm());

	{
		Motor scoped(PORT_D);

		scoped.setPWM(70);
		clock.sleep(300);
	}
	before = ev3_motor_get_counts(EV3_PORT_D);
	clock.sleep(500);
	syslog(LOG_NOTICE, "libcpp: motor destructor left power %d, moved %d", ev3_motor_get_power(EV3_PORT_D),
	       (int)(ev3_motor_get_counts(EV3_PORT_D) - before));
}

/* Steering: the inner wheel at (100 - |ratio|) % of the outer one. */
static void test_steering(Clock& clock)
{
	static const int ratios[] = { 0, 25, -50, 100 };
	Motor left(PORT_A), right(PORT_D);
	Steering steering(left, right);

	for (unsigned i = 0; i < sizeof(ratios) / sizeof(ratios[0]); i++) {
		int32_t l0, r0;

		steering.setPower(60, ratios[i]);
		clock.sleep(400);   /* up to speed */
		l0 = left.getCount();
		r0 = right.getCount();
		clock.sleep(1000);
		syslog(LOG_NOTICE, "libcpp: steering ratio %d left %d right %d", ratios[i],
		       (int)(left.getCount() - l0), (int)(right.getCount() - r0));
	}
	steering.setPower(0, 0);
}

/* Clock: now() from the start and from reset(), wait() and sleep(). */
static void test_clock(void)
{
	Clock clock;
	uint32_t t0, t1, t2;

	clock.wait(120);
	t0 = clock.now();
	clock.sleep(80);
	t1 = clock.now();
	clock.reset();
	t2 = clock.now();
	syslog(LOG_NOTICE, "libcpp: clock wait 120 -> %u, sleep 80 -> %u, reset -> %u", (unsigned)t0,
	       (unsigned)t1, (unsigned)t2);
}

/* The sensors: each read equals EV3RT's C call on the same port. */
static void test_sensors(Clock& clock)
{
	TouchSensor touch(PORT_1);
	GyroSensor gyro(PORT_2);
	ColorSensor color(PORT_3);
	SonarSensor sonar(PORT_4);
	rgb_raw_t rgb;
	int16_t rate;
	SYSTIM now = 0;

	syslog(LOG_NOTICE, "libcpp: touch before %d, the global object's %d", (int)touch.isPressed(),
	       (int)globalTouch.isPressed());
	while (!touch.isPressed())
		clock.sleep(10);
	get_tim(&now);
	syslog(LOG_NOTICE, "libcpp: touch pressed at %u ms, C says %d", (unsigned)now,
	       (int)ev3_touch_sensor_is_pressed(EV3_PORT_1));

	syslog(LOG_NOTICE, "libcpp: gyro angle %d rate %d", gyro.getAngle(), gyro.getAnglerVelocity());
	gyro.setOffset(5);
	rate = gyro.getAnglerVelocity();
	syslog(LOG_NOTICE, "libcpp: gyro offset 5 rate %d C rate %d", rate, ev3_gyro_sensor_get_rate(EV3_PORT_2));
	gyro.reset();
	syslog(LOG_NOTICE, "libcpp: gyro reset angle %d", gyro.getAngle());

	syslog(LOG_NOTICE, "libcpp: color brightness %d C %d", color.getBrightness(),
	       ev3_color_sensor_get_reflect(EV3_PORT_3));
	syslog(LOG_NOTICE, "libcpp: color ambient %d C %d", color.getAmbient(),
	       ev3_color_sensor_get_ambient(EV3_PORT_3));
	syslog(LOG_NOTICE, "libcpp: color number %d C %d", (int)color.getColorNumber(),
	       (int)ev3_color_sensor_get_color(EV3_PORT_3));
	color.getRawColor(rgb);
	{
		rgb_raw_t c_rgb;

		ev3_color_sensor_get_rgb_raw(EV3_PORT_3, &c_rgb);
		syslog(LOG_NOTICE, "libcpp: color raw %u %u %u C %u %u %u", rgb.r, rgb.g, rgb.b, c_rgb.r, c_rgb.g,
		       c_rgb.b);
	}

	syslog(LOG_NOTICE, "libcpp: sonar distance %d C %d listen %d", sonar.getDistance(),
	       ev3_ultrasonic_sensor_get_distance(EV3_PORT_4), (int)sonar.listen());
}

void main_task(intptr_t unused)
{
	Clock clock;

	syslog(LOG_NOTICE, "libcpp: global gyro set %d, angle %d", (int)(globalGyro != NULL),
	       globalGyro != NULL ? globalGyro->getAngle() : -1);
	test_clock();
	test_motor(clock);
	test_steering(clock);
	test_sensors(clock);
	syslog(LOG_NOTICE, "libcpp: done");
}
