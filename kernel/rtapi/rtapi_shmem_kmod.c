/* SPDX-License-Identifier: GPL-2.0-or-later */
/* rtapi_shmem_kmod.c - shared memory (rtapi_shmem(3rtapi)) in the kernel flavor:
 * vmalloc_user() segments, found by key, exported to userspace by the misc device
 * /dev/rtapi (ioctl lookup by key, mmap at offset id * PAGE_SIZE). A segment lives
 * while a module uses it or a process maps it. */
#include <linux/module.h>
#include <linux/fs.h>
#include <linux/mm.h>
#include <linux/vmalloc.h>
#include <linux/miscdevice.h>
#include <linux/uaccess.h>
#include <linux/seq_file.h>
#include <linux/slab.h>
#include "rtapi_kmod.h"
#include "rtapi_shmem_kmod.h"

struct rtapi_shmem {
	bool used;
	int key;
	unsigned long size;		/* as requested */
	void *mem;			/* vmalloc_user: zeroed, page aligned */
	DECLARE_BITMAP(modules, RTAPI_MAX_MODULES);	/* modules that called shmem_new */
	int mappings;			/* userspace VMAs */
	unsigned long ro_len;		/* protected: read-only below this (page aligned) */
};

/* Keys whose segments are protected (rtapi_shmem_kmod_protect_key); guarded by
 * rtapi_kmod_lock, kept for rtapi.ko's lifetime so that no segment is ever created
 * unprotected under such a key. */
#define MAX_PROTECTED 4
static struct {
	int key;
	unsigned long ro_len;
} protected_keys[MAX_PROTECTED];
static int nprotected;

static const struct rtapi_dev_hook *dev_hook;	/* guarded by rtapi_kmod_lock */

/* Per open file of /dev/rtapi. */
struct dev_file {
	unsigned long hook_state;	/* the hook's (hal_lib: holds the HAL mutex) */
};

static struct rtapi_shmem segs[RTAPI_MAX_SHMEMS];	/* index 0 unused: ids are > 0 */

static void seg_release_if_unused(struct rtapi_shmem *s)	/* lock held */
{
	if (!s->used || s->mappings || !bitmap_empty(s->modules, RTAPI_MAX_MODULES))
		return;
	vfree(s->mem);
	s->mem = NULL;
	s->used = false;
}

int rtapi_shmem_new(int key, int module_id, unsigned long int size)
{
	int id, free_id = 0, rc;

	if (size == 0)
		return -EINVAL;
	mutex_lock(&rtapi_kmod_lock);
	if (!rtapi_module_valid(module_id)) {
		rc = -EINVAL;
		goto out;
	}
	for (id = 1; id < RTAPI_MAX_SHMEMS; id++) {
		if (!segs[id].used) {
			if (!free_id)
				free_id = id;
			continue;
		}
		if (segs[id].key != key)
			continue;
		if (size > segs[id].size) {
			rtapi_print_msg(RTAPI_MSG_ERR,
					"RTAPI: shmem key 0x%08x: %lu bytes asked, segment has %lu\n",
					key, size, segs[id].size);
			rc = -EINVAL;
			goto out;
		}
		if (test_and_set_bit(module_id, segs[id].modules)) {
			rc = -EINVAL;	/* one attach per module, like the other flavor */
			goto out;
		}
		rc = id;
		goto out;
	}
	if (!free_id) {
		rtapi_print_msg(RTAPI_MSG_ERR, "RTAPI: all %d shmem slots in use\n",
				RTAPI_MAX_SHMEMS - 1);
		rc = -ENOMEM;
		goto out;
	}
	segs[free_id].mem = vmalloc_user(size);
	if (!segs[free_id].mem) {
		rc = -ENOMEM;
		goto out;
	}
	segs[free_id].used = true;
	segs[free_id].key = key;
	segs[free_id].size = size;
	segs[free_id].mappings = 0;
	segs[free_id].ro_len = 0;
	for (id = 0; id < nprotected; id++)
		if (protected_keys[id].key == key)
			segs[free_id].ro_len = PAGE_ALIGN(protected_keys[id].ro_len);
	bitmap_zero(segs[free_id].modules, RTAPI_MAX_MODULES);
	set_bit(module_id, segs[free_id].modules);
	rc = free_id;
out:
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_shmem_new);

int rtapi_shmem_delete(int shmem_id, int module_id)
{
	struct rtapi_shmem *s;
	int rc = 0;

	if (shmem_id <= 0 || shmem_id >= RTAPI_MAX_SHMEMS || module_id <= 0 ||
	    module_id >= RTAPI_MAX_MODULES)
		return -EINVAL;
	mutex_lock(&rtapi_kmod_lock);
	s = &segs[shmem_id];
	if (!s->used || !test_and_clear_bit(module_id, s->modules))
		rc = -EINVAL;
	else
		seg_release_if_unused(s);
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_shmem_delete);

int rtapi_shmem_getptr(int shmem_id, void **ptr)
{
	if (shmem_id <= 0 || shmem_id >= RTAPI_MAX_SHMEMS || !READ_ONCE(segs[shmem_id].used))
		return -EINVAL;
	*ptr = segs[shmem_id].mem;
	return 0;
}
EXPORT_SYMBOL(rtapi_shmem_getptr);

int rtapi_shmem_kmod_protect_key(int key, unsigned long ro_len)
{
	int i, rc = 0;

	mutex_lock(&rtapi_kmod_lock);
	for (i = 0; i < nprotected && protected_keys[i].key != key; i++)
		;
	if (i == MAX_PROTECTED) {
		rc = -ENOMEM;
	} else {
		protected_keys[i].key = key;
		protected_keys[i].ro_len = ro_len;
		if (i == nprotected)
			nprotected++;
	}
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}
EXPORT_SYMBOL(rtapi_shmem_kmod_protect_key);

void rtapi_kmod_set_dev_hook(const struct rtapi_dev_hook *hook)
{
	mutex_lock(&rtapi_kmod_lock);
	dev_hook = hook;
	mutex_unlock(&rtapi_kmod_lock);
}
EXPORT_SYMBOL(rtapi_kmod_set_dev_hook);

/* --- /dev/rtapi --- */

/* The registered hook with a reference on its module, or NULL. */
static const struct rtapi_dev_hook *hook_get(void)
{
	const struct rtapi_dev_hook *h;

	mutex_lock(&rtapi_kmod_lock);
	h = dev_hook;
	if (h && !try_module_get(h->owner))
		h = NULL;	/* being unloaded */
	mutex_unlock(&rtapi_kmod_lock);
	return h;
}

static int dev_open(struct inode *inode, struct file *f)
{
	struct dev_file *df = kzalloc(sizeof(*df), GFP_KERNEL);

	if (!df)
		return -ENOMEM;
	f->private_data = df;
	return 0;
}

static int dev_release(struct inode *inode, struct file *f)
{
	struct dev_file *df = f->private_data;
	const struct rtapi_dev_hook *h;

	if (df->hook_state) {
		h = hook_get();
		if (h) {
			h->release(&df->hook_state);
			module_put(h->owner);
		}
	}
	kfree(df);
	return 0;
}

static long dev_ioctl(struct file *f, unsigned int cmd, unsigned long arg)
{
	struct dev_file *df = f->private_data;
	struct rtapi_shmem_query q;
	int id;

	if (cmd != RTAPI_IOC_SHMEM_LOOKUP) {
		const struct rtapi_dev_hook *h = hook_get();
		long rc;

		if (!h)
			return -ENOTTY;
		rc = h->ioctl(&df->hook_state, cmd, arg);
		module_put(h->owner);
		return rc;
	}
	if (copy_from_user(&q, (void __user *)arg, sizeof(q)))
		return -EFAULT;
	mutex_lock(&rtapi_kmod_lock);
	for (id = 1; id < RTAPI_MAX_SHMEMS; id++)
		if (segs[id].used && segs[id].key == q.key)
			break;
	if (id < RTAPI_MAX_SHMEMS) {
		q.id = id;
		q.size = segs[id].size;
	}
	mutex_unlock(&rtapi_kmod_lock);
	if (id == RTAPI_MAX_SHMEMS)
		return -ENOENT;
	if (copy_to_user((void __user *)arg, &q, sizeof(q)))
		return -EFAULT;
	return 0;
}

static void vma_open(struct vm_area_struct *vma)
{
	struct rtapi_shmem *s = vma->vm_private_data;

	mutex_lock(&rtapi_kmod_lock);
	s->mappings++;
	mutex_unlock(&rtapi_kmod_lock);
}

static void vma_close(struct vm_area_struct *vma)
{
	struct rtapi_shmem *s = vma->vm_private_data;

	mutex_lock(&rtapi_kmod_lock);
	s->mappings--;
	seg_release_if_unused(s);
	mutex_unlock(&rtapi_kmod_lock);
}

static const struct vm_operations_struct seg_vm_ops = {
	.open = vma_open,
	.close = vma_close,
};

static int dev_mmap(struct file *f, struct vm_area_struct *vma)
{
	unsigned long id = vma->vm_pgoff & ((1ul << RTAPI_SHMEM_ID_BITS) - 1);
	unsigned long first = vma->vm_pgoff >> RTAPI_SHMEM_ID_BITS;	/* page in the segment */
	unsigned long len = vma->vm_end - vma->vm_start;
	struct rtapi_shmem *s;
	int rc;

	if (id == 0 || id >= RTAPI_MAX_SHMEMS)
		return -EINVAL;
	mutex_lock(&rtapi_kmod_lock);
	s = &segs[id];
	if (!s->used || first >= (PAGE_ALIGN(s->size) >> PAGE_SHIFT) ||
	    len > PAGE_ALIGN(s->size) - (first << PAGE_SHIFT)) {
		rc = -EINVAL;
		goto out;
	}
	/* A protected segment: the part below ro_len never maps writable, nor can it
	 * become so (VM_MAYWRITE cleared: mprotect refuses), and a piece never straddles
	 * the boundary. */
	if ((first << PAGE_SHIFT) < s->ro_len) {
		if ((first << PAGE_SHIFT) + len > s->ro_len || (vma->vm_flags & VM_WRITE)) {
			rc = -EPERM;
			goto out;
		}
		vma->vm_flags &= ~VM_MAYWRITE;
	}
	rc = remap_vmalloc_range(vma, s->mem, first);
	if (rc)
		goto out;
	vma->vm_private_data = s;
	vma->vm_ops = &seg_vm_ops;
	s->mappings++;
out:
	mutex_unlock(&rtapi_kmod_lock);
	return rc;
}

static const struct file_operations dev_fops = {
	.owner = THIS_MODULE,
	.open = dev_open,
	.release = dev_release,
	.unlocked_ioctl = dev_ioctl,
	.compat_ioctl = dev_ioctl,	/* fixed-width struct: same layout for 32-bit callers */
	.mmap = dev_mmap,
};

static struct miscdevice dev = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = RTAPI_DEVICE_NAME,
	.fops = &dev_fops,
	.mode = 0660,	/* root and the 'hal' group (udev rule: firmware/udev/) */
};

void rtapi_shmem_show(struct seq_file *m)
{
	int id;

	mutex_lock(&rtapi_kmod_lock);
	seq_puts(m, "ID  KEY        SIZE       MAPPINGS MODULES\n");
	for (id = 1; id < RTAPI_MAX_SHMEMS; id++) {
		struct rtapi_shmem *s = &segs[id];
		int mod;

		if (!s->used)
			continue;
		seq_printf(m, "%-3d 0x%08x %-10lu %-8d", id, s->key, s->size, s->mappings);
		for_each_set_bit(mod, s->modules, RTAPI_MAX_MODULES)
			seq_printf(m, " %s", rtapi_module_name(mod) ? rtapi_module_name(mod) : "?");
		seq_putc(m, '\n');
	}
	mutex_unlock(&rtapi_kmod_lock);
}

int rtapi_shmem_kmod_init(void)
{
	int rc = misc_register(&dev);

	if (rc)
		printk(KERN_ERR "RTAPI: cannot register /dev/%s (%d)\n", RTAPI_DEVICE_NAME, rc);
	return rc;
}

void rtapi_shmem_kmod_exit(void)
{
	int id;

	misc_deregister(&dev);
	/* No module can still hold a segment (they depend on rtapi.ko); a process may
	 * still map one: its pages stay referenced by the mapping until it goes. */
	for (id = 1; id < RTAPI_MAX_SHMEMS; id++) {
		if (segs[id].used && segs[id].mappings)
			printk(KERN_WARNING "RTAPI: shmem 0x%08x still mapped at unload\n",
			       segs[id].key);
		if (segs[id].used)
			vfree(segs[id].mem);
		segs[id].used = false;
	}
}
