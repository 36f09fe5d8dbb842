/*
 * test_base.c — the base headers: ioctl encoding, errno numbering, min/max/clamp,
 * bit helpers, container_of, kstrto*, string helpers, scnprintf.
 */
#include "tap.h"
#include <linux/types.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux/ioctl.h>
#include <linux/bits.h>
#include <linux/string.h>

struct uart_conn12 { u8 bytes[12]; };     /* LEGO's UART_SET_CONN argument: 12 bytes */
struct mode_info60 { u8 bytes[60]; };     /* 0x3C bytes: UART_READ_MODE_INFO */

struct outer {
	int a;
	long member;
	char c;
};

int main(void)
{
	tap_plan(45);

	is_int(_IOWR('u', 0, struct uart_conn12), 0xC00C7500U, "_IOWR('u',0,12 bytes) = 0xC00C7500");
	is_int(_IOWR('u', 1, struct mode_info60), 0xC03C7501U, "_IOWR('u',1,60 bytes) = 0xC03C7501");
	is_int(_IO('a', 3), 0x6103, "_IO encoding");
	is_int(_IOR('b', 2, u32), 0x80046202U, "_IOR encoding");
	is_int(_IOW('b', 2, u16), 0x40026202U, "_IOW encoding");
	is_int(_IOC_SIZE(0xC00C7500U), 12, "_IOC_SIZE decodes");
	is_int(_IOC_DIR(0xC00C7500U), _IOC_READ | _IOC_WRITE, "_IOC_DIR decodes");
	is_int(_IOC_TYPE(0xC00C7500U), 'u', "_IOC_TYPE decodes");
	is_int(_IOC_NR(0xC03C7501U), 1, "_IOC_NR decodes");

	is_int(EAGAIN, 11, "EAGAIN is 11");
	is_int(EBUSY, 16, "EBUSY is 16");
	is_int(EFAULT, 14, "EFAULT is 14");
	is_int(ETIMEDOUT, 110, "ETIMEDOUT is 110");
	is_int(ERESTARTSYS, 512, "ERESTARTSYS is 512");
	is_int(ENOTSUPP, 524, "ENOTSUPP is 524");
	is_int(ENOIOCTLCMD, 515, "ENOIOCTLCMD is 515");

	{
		int a = 3, b = -7;
		unsigned int u = 5, v = 9;
		int calls = 0;

		is_int(min(a, b), -7, "min of ints");
		is_int(max(a, b), 3, "max of ints");
		is_int(min(u, v), 5, "min of unsigned");
		is_int(max_t(int, u, b), 5, "max_t converts to the named type");
		is_int(min_t(u8, 300, 20), 20, "min_t truncates like Linux (300 -> 44 as u8, 20 smaller)");
		is_int(clamp(a, -1, 2), 2, "clamp above");
		is_int(clamp(b, -1, 2), -1, "clamp below");
		is_int(clamp(1, -1, 2), 1, "clamp inside");
		is_int(clamp_t(int, 9U, 0, 4), 4, "clamp_t");
		is_int(min((++calls, a), b), -7, "min with side effect");
		is_int(calls, 1, "min evaluates each argument once");
		is_int(max3(1, 9, 4), 9, "max3");
		{
			static char array_sized_by_min[min(3, 5)];
			is_int(sizeof(array_sized_by_min), 3, "min of constants is a constant expression");
		}
	}

	{
		int arr[7];
		struct outer o;
		long *mp = &o.member;

		is_int(ARRAY_SIZE(arr), 7, "ARRAY_SIZE");
		is_int(DIV_ROUND_UP(10, 4), 3, "DIV_ROUND_UP");
		is_int(DIV_ROUND_CLOSEST(10, 4), 3, "DIV_ROUND_CLOSEST rounds halves up");
		ok(container_of(mp, struct outer, member) == &o, "container_of finds the structure");
		is_int(BIT(5), 32, "BIT");
		is_u64(GENMASK(7, 4), 0xf0, "GENMASK(7,4)");
		is_u64(GENMASK_ULL(39, 32), 0xff00000000ULL, "GENMASK_ULL");
	}

	{
		int i = 0;
		unsigned long ul = 0;
		bool bl = false;

		ok(kstrtoint("-42", 10, &i) == 0 && i == -42, "kstrtoint negative");
		ok(kstrtoul("0x1f\n", 0, &ul) == 0 && ul == 31, "kstrtoul auto base with newline");
		is_int(kstrtoint("12a", 10, &i), -EINVAL, "kstrtoint rejects trailing junk");
		is_int(kstrtoint("3000000000", 10, &i), -ERANGE, "kstrtoint range check");
		ok(kstrtobool("on", &bl) == 0 && bl, "kstrtobool on");
	}

	{
		char buf[8];

		is_int(strscpy(buf, "abc", sizeof(buf)), 3, "strscpy returns length");
		is_int(strscpy(buf, "abcdefghij", sizeof(buf)), -E2BIG, "strscpy reports truncation");
		is_str(buf, "abcdefg", "strscpy terminates");
		is_int(scnprintf(buf, sizeof(buf), "%d", 123456789), 7, "scnprintf returns stored length");
	}
	return tap_done();
}
