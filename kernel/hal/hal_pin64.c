/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hal_pin64.c - constructors of the 64-bit integer pins and parameters (s64, u64,
 * LinuxCNC 2.9's types). The records and checks are those of hal_pin.c/hal_param.c;
 * this file only names the types. */
#include "hal_internal.h"

int hal_pin_s64_new(const char *name, hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_S64, dir, (void **)data_ptr_addr, comp_id);
}

int hal_pin_u64_new(const char *name, hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id)
{
	return hal_pin_new(name, HAL_U64, dir, (void **)data_ptr_addr, comp_id);
}

int hal_param_s64_new(const char *name, hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_S64, dir, (void *)data_addr, comp_id);
}

int hal_param_u64_new(const char *name, hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id)
{
	return hal_param_new(name, HAL_U64, dir, (void *)data_addr, comp_id);
}

static int pin_newfv(hal_type_t type, hal_pin_dir_t dir, void **data_ptr_addr, int comp_id,
		     const char *fmt, va_list ap)
{
	char name[HAL_NAME_LEN + 1];
	int err = hal_format_name(name, "pin", fmt, ap);

	return err ? err : hal_pin_new(name, type, dir, data_ptr_addr, comp_id);
}

static int param_newfv(hal_type_t type, hal_param_dir_t dir, void *data_addr, int comp_id,
		       const char *fmt, va_list ap)
{
	char name[HAL_NAME_LEN + 1];
	int err = hal_format_name(name, "parameter", fmt, ap);

	return err ? err : hal_param_new(name, type, dir, data_addr, comp_id);
}

int hal_pin_s64_newf(hal_pin_dir_t dir, hal_s64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_S64, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_pin_u64_newf(hal_pin_dir_t dir, hal_u64_t **data_ptr_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = pin_newfv(HAL_U64, dir, (void **)data_ptr_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_param_s64_newf(hal_param_dir_t dir, hal_s64_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_S64, dir, (void *)data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}

int hal_param_u64_newf(hal_param_dir_t dir, hal_u64_t *data_addr, int comp_id, const char *fmt, ...)
{
	va_list ap;
	int rc;

	va_start(ap, fmt);
	rc = param_newfv(HAL_U64, dir, (void *)data_addr, comp_id, fmt, ap);
	va_end(ap);
	return rc;
}
