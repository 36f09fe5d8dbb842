/*
 * test_idr.c — the IDA: the smallest free ID in a range, IDs given back
 * and taken again, the limits (-ENOSPC past LX_IDA_MAX or the range's end,
 * -EINVAL for an empty range), ida_destroy, and freeing an ID not taken
 * reported.
 */
#include "lx_log_test.h"
#include <linux/errno.h>
#include <linux/idr.h>

static DEFINE_IDA(test_ida);

static void body(void)
{
	int i, last = 0;

	ok(ida_is_empty(&test_ida), "a new IDA is empty");
	is_int(ida_alloc(&test_ida, GFP_KERNEL), 0, "the first ID is 0");
	is_int(ida_alloc(&test_ida, GFP_KERNEL), 1, "then 1");
	is_int(ida_alloc_min(&test_ida, 5, GFP_KERNEL), 5, "ida_alloc_min(5): 5");
	ida_free(&test_ida, 0);
	is_int(ida_alloc(&test_ida, GFP_KERNEL), 0, "a freed ID is the smallest again");
	is_int(ida_alloc_range(&test_ida, 5, 6, GFP_KERNEL), 6, "[5, 6] with 5 taken: 6");
	is_int(ida_alloc_range(&test_ida, 5, 6, GFP_KERNEL), -ENOSPC, "[5, 6] full: -ENOSPC");
	is_int(ida_alloc_range(&test_ida, 7, 6, GFP_KERNEL), -EINVAL, "an empty range: -EINVAL");
	is_int(ida_alloc_max(&test_ida, 3, GFP_KERNEL), 2, "ida_alloc_max(3): 2");
	for (i = 0; i < LX_IDA_MAX; i++) {
		int id = ida_alloc(&test_ida, GFP_KERNEL);

		if (id < 0)
			break;
		last = id;
	}
	ok(i == LX_IDA_MAX - 5 && last == LX_IDA_MAX - 1, "IDs up to LX_IDA_MAX - 1, then -ENOSPC (%d, %d)", i, last);
	is_int(DC_EXPECT_BUG(ida_free(&test_ida, LX_IDA_MAX + 3)), 1, "freeing an ID never taken is reported");
	ida_destroy(&test_ida);
	ok(ida_is_empty(&test_ida), "ida_destroy gives every ID back");
}

int main(void)
{
	tap_plan(13);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
