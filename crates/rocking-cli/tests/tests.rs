//! Integration tests of the `rocking` binary: the real executable on real files
//! in temporary folders (one test binary, ripgrep style).

mod util;

mod assess;
mod check;
mod errors;
mod folder;
mod fragility;
mod guard;
mod hardening;
mod inventory;
mod keys;
mod regression_assess_interrupted;
mod regression_assess_plot;
mod regression_assess_record_fails_to_run;
mod regression_belfry_d0_row;
mod regression_belfry_note_a0;
mod regression_block_name_on_one_line;
mod regression_concurrent_runs;
mod regression_csv_injection;
mod regression_fragility_with_blocks;
mod regression_interrupted_sweep;
mod regression_inventory_block_columns;
mod regression_inventory_interrupted;
mod regression_inventory_no_tower_assessed;
mod regression_inventory_place_given_once;
mod regression_lambda_figure_names_the_record;
mod regression_merge_bounds;
mod regression_merge_into_a_used_folder;
mod regression_output_folder_manifest;
mod regression_record_set_error_order;
mod regression_refused_run_leaves_no_folder;
mod regression_spectrum_dt;
mod regression_spectrum_hangs;
mod regression_spectrum_period_count;
mod regression_spectrum_record_peak;
mod regression_spectrum_site_fits_as_assess;
mod regression_stack_seat_impulse_ratio;
mod regression_town_table_columns;
mod run;
mod shard;
mod spectrum;
mod sweep;
mod vertical;
