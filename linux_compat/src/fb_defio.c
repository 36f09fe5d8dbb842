/*
 * fb_defio.c — deferred I/O for frame buffers (linux/fb.h): writes to the
 * mapped frame memory list their pages and schedule the driver's
 * deferred_io after fbdefio->delay; the work hands it the list and empties
 * it, so the next write to a page lists it again (Linux write-protects the
 * pages again at that point).  The write "fault" comes from
 * lx_fb_mmap_written (linux_compat/fbdev.h).
 */
#include <linux/fb.h>
#include <linux/jiffies.h>
#include <linux/kernel.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/workqueue.h>
#include <linux_compat/fbdev.h>

/* The work: the driver gets the written pages, in the order written (or sorted). */
static void fb_deferred_io_work(struct work_struct *work)
{
	struct fb_info *info = container_of(work, struct fb_info, deferred_work.work);
	struct fb_deferred_io *fbdefio = info->fbdefio;
	struct fb_deferred_io_pageref *pageref, *next;

	mutex_lock(&fbdefio->lock);
	fbdefio->deferred_io(info, &fbdefio->pagereflist);
	list_for_each_entry_safe(pageref, next, &fbdefio->pagereflist, list)
		list_del_init(&pageref->list);
	mutex_unlock(&fbdefio->lock);
}

int fb_deferred_io_init(struct fb_info *info)
{
	struct fb_deferred_io *fbdefio;
	unsigned long i, len;

	might_sleep();
	if (!info || !info->fbdefio || !info->fbdefio->deferred_io)
		return -EINVAL;
	fbdefio = info->fbdefio;
	len = info->fix.smem_len;
	if (!len)
		len = info->screen_size;
	mutex_init(&fbdefio->lock);
	INIT_LIST_HEAD(&fbdefio->pagereflist);
	if (!fbdefio->delay)
		fbdefio->delay = HZ;
	info->npagerefs = PAGE_ALIGN(len) >> PAGE_SHIFT;
	info->pagerefs = kcalloc(info->npagerefs, sizeof(*info->pagerefs), GFP_KERNEL);
	if (!info->pagerefs)
		return -ENOMEM;
	for (i = 0; i < info->npagerefs; i++) {
		info->pagerefs[i].offset = i << PAGE_SHIFT;
		INIT_LIST_HEAD(&info->pagerefs[i].list);
	}
	INIT_DELAYED_WORK(&info->deferred_work, fb_deferred_io_work);
	return 0;
}

void fb_deferred_io_cleanup(struct fb_info *info)
{
	might_sleep();
	if (!info || !info->pagerefs)
		return;
	cancel_delayed_work_sync(&info->deferred_work);
	kfree(info->pagerefs);
	info->pagerefs = NULL;
	info->npagerefs = 0;
}

int fb_deferred_io_mmap(struct fb_info *info, struct vm_area_struct *vma)
{
	unsigned long len = vma->vm_end - vma->vm_start;
	unsigned long off = vma->vm_pgoff << PAGE_SHIFT;

	if (!info->screen_buffer || off > info->npagerefs << PAGE_SHIFT ||
	    len > (info->npagerefs << PAGE_SHIFT) - off)
		return -EINVAL;
	vma->vm_flags |= VM_DONTEXPAND | VM_DONTDUMP;
	vma->vm_private_data = info;
	return remap_pfn_range(vma, vma->vm_start, virt_to_pfn(info->screen_buffer + off), len,
			       vma->vm_page_prot);
}

/* What page_mkwrite does for the page at offset: list it (once) and schedule the work. */
static void fb_deferred_io_page_written(struct fb_info *info, unsigned long offset)
{
	struct fb_deferred_io *fbdefio = info->fbdefio;
	struct fb_deferred_io_pageref *pageref = &info->pagerefs[offset >> PAGE_SHIFT];
	struct fb_deferred_io_pageref *cur;
	struct list_head *pos = &fbdefio->pagereflist;

	mutex_lock(&fbdefio->lock);
	if (fbdefio->first_io && list_empty(&fbdefio->pagereflist))
		fbdefio->first_io(info);
	if (list_empty(&pageref->list)) {
		pageref->page = lx_virt_to_page(info->screen_buffer + pageref->offset);
		if (fbdefio->sort_pagereflist) {
			list_for_each_entry(cur, &fbdefio->pagereflist, list) {
				if (cur->offset > pageref->offset) {
					pos = &cur->list;
					break;
				}
			}
		}
		list_add_tail(&pageref->list, pos);
	}
	mutex_unlock(&fbdefio->lock);
	schedule_delayed_work(&info->deferred_work, fbdefio->delay);
}

int lx_fb_mmap_written(struct file *file, unsigned long offset, size_t len)
{
	struct fb_info *info;
	unsigned long page, last;

	might_sleep();
	if (!lx_fb_file(file))
		return -EBADF;
	info = file->private_data;
	if (!len)
		return 0;
	if (!info->fbdefio || !info->pagerefs)
		return offset + len <= PAGE_ALIGN(info->fix.smem_len) ? 0 : -EINVAL;
	if (offset >= info->npagerefs << PAGE_SHIFT || len > (info->npagerefs << PAGE_SHIFT) - offset)
		return -EINVAL;
	last = (offset + len - 1) >> PAGE_SHIFT;
	for (page = offset >> PAGE_SHIFT; page <= last; page++)
		fb_deferred_io_page_written(info, page << PAGE_SHIFT);
	return 0;
}
