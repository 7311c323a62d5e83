# `puncture fit curve` (included by CMakeLists.txt): synthetic records of the default membrane
# (indentation_record*.csv, .tsv: the model's curve plus seeded noise) fitted back; bad records
# and flags refused naming the file, line, column or flag.
puncture_cli_test(fit_curve_summary
  STDOUT "  shear-modulus +0.0[56][0-9]* \\+- ${number} MPa  95 % interval \\[${number}, ${number}\\]"
  STDOUT2 "  jlim +1[0-9][0-9][0-9.]* \\+- ${number}  95 % interval"
  STDOUT3 "correlation +shear-modulus +jlim"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus,jlim --contact-depth 2)
puncture_cli_test(fit_curve_found_contact_and_perforation
  STDOUT "from the contact at 5.1699 mm \\(found\\); perforation at 34.869 mm, 0.70215 N"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus)
puncture_cli_test(fit_curve_semicolon_decimal_comma_json
  JSON_KEYS "fit.free.0.value fit.free.0.ci95_lower fit.correlation.1.0 tests.0.model_force_n.5 tests.0.measured_puncture.force_n"
  ARGS fit curve ${dir}/indentation_record_semicolon.csv --free shear-modulus,jlim
       --depth-column "Weg [m]" --force-column 1 --depth-unit m --force-unit kN
       --contact-depth 0.002 --format json)
puncture_cli_test(fit_curve_manifest_csv
  STDOUT "^test,depth_mm,force_n,model_force_n,residual_n\n"
  STDOUT2 "indentation_record_4mm.tsv,${number},"
  ARGS fit curve --manifest ${dir}/fit_curve_two_tests.toml --free shear-modulus,jlim
       --format csv)
puncture_cli_test(fit_curve_too_stiff RC 2
  STDERR "shear-modulus = 0.03 lies on a bound"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus --contact-depth 2
       --bound shear-modulus:0.01:0.03)
puncture_cli_bad_input(fit_curve_unknown_free
  "--free: unknown parameter 'modulus' \\(choose from: shear-modulus, jlim"
  fit curve ${dir}/indentation_record.csv --free modulus)
puncture_cli_bad_input(fit_curve_missing_column
  "indentation_record.csv:2: missing depth column 'depth' \\(the header has: time_s, depth_mm, force_n\\)"
  fit curve ${dir}/indentation_record.csv --free jlim --depth-column depth)
puncture_cli_bad_input(fit_curve_non_numeric_cell
  "indentation_bad_cell.csv:4: column 2 \\(force_n\\): 'n/a' is not a number"
  fit curve ${dir}/indentation_bad_cell.csv --free jlim --contact-depth 0)
puncture_cli_bad_input(fit_curve_decreasing_depth
  "indentation_backwards.csv:4: column 1 \\(depth_mm\\): the depth decreases"
  fit curve ${dir}/indentation_backwards.csv --free jlim --contact-depth 0)
puncture_cli_bad_input(fit_curve_too_few_points
  "indentation_three_points.csv: 3 points past the contact point: fewer than the 4 needed for 3 free parameters \\(--free\\)"
  fit curve ${dir}/indentation_three_points.csv --free shear-modulus,jlim,friction
  --contact-depth 0)
puncture_cli_bad_input(fit_curve_critical_i1_without_puncture
  "--free: critical-i1 is free but no test has a puncture point"
  fit curve ${dir}/indentation_record.csv --free critical-i1 --contact-depth 2 --ignore-puncture)
puncture_cli_bad_input(fit_curve_manifest_unknown_key
  "fit_curve_unknown_key.toml:3: key 'indentor-radius': unknown"
  fit curve --manifest ${dir}/fit_curve_unknown_key.toml --free jlim)
puncture_cli_bad_input(fit_curve_bad_bound "--bound: expected NAME:LO:HI"
  fit curve ${dir}/indentation_record.csv --free jlim --bound jlim:500:50)
puncture_cli_bad_input(fit_curve_no_files "give the CSV records"
  fit curve --free jlim)
puncture_cli_test(fit_curve_stick_threshold_alone
  STDOUT "  stick-threshold +0\\.[23][0-9]* N  95 % interval \\[0\\.2[0-9]*, 0\\.3[0-9]*\\] from the profile"
  ARGS fit curve ${dir}/indentation_record_stick.csv --free stick-threshold --stick force:0.25
       --contact-depth 2)
puncture_cli_bad_input(fit_curve_stick_threshold_without_threshold_rule
  "--free: test .*indentation_record.csv: stick-threshold is free but the stick rule 'none' has no threshold"
  fit curve ${dir}/indentation_record.csv --free shear-modulus,stick-threshold --contact-depth 2)
# A record with a switch (the default membrane held until 0.3 N, indentation_record_stick.csv):
# the threshold from the profile, its interval holding 0.3 N.
puncture_cli_test(fit_curve_stick_threshold
  STDOUT "  stick-threshold +0\\.[23][0-9]* N  95 % interval \\[0\\.2[0-9]*, 0\\.3[0-9]*\\] from the profile"
  STDOUT2 "the switch lies between the measured depths 1[67]\\.[0-9]* and 1[67]\\.[0-9]* mm"
  ARGS fit curve ${dir}/indentation_record_stick.csv --free shear-modulus,stick-threshold
       --stick force:0.25 --contact-depth 2)
# Each record's contact offset: the found contact of indentation_record.csv is 3.17 mm late
# (the true contact at 2 mm).
puncture_cli_test(fit_curve_contact_offset
  STDOUT "  offset 1 +-3\\.[0-9]* \\+- ${number} mm  95 % interval \\[-${number}, -${number}\\] \\(test .*indentation_record.csv\\)"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus,jlim,contact-offset)
puncture_cli_test(fit_curve_contact_offset_json
  JSON_KEYS "fit.free.1.value fit.free.1.test fit.free.0.interval"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus,contact-offset
       --format json)
puncture_cli_bad_input(fit_curve_column_position_missing
  "indentation_record.csv:2: the force column 5 does not exist: the line has 3 fields"
  fit curve ${dir}/indentation_record.csv --free jlim --force-column 5)
puncture_cli_bad_input(fit_curve_short_row
  "indentation_short_row.csv:4: column 2 \\(force_n\\) is missing: the line has 1 field"
  fit curve ${dir}/indentation_short_row.csv --free jlim --contact-depth 0)
puncture_cli_test(fit_curve_huber
  STDOUT "  shear-modulus +0.0[56][0-9]* \\+- ${number} MPa"
  ARGS fit curve ${dir}/indentation_record.csv --free shear-modulus --contact-depth 2
       --loss huber --loss-scale 0.005)
puncture_cli_bad_input(fit_curve_loss_without_scale "--loss-scale: --loss cauchy needs a scale"
  fit curve ${dir}/indentation_record.csv --free jlim --loss cauchy)
# A manifest test with its own probe: a cone's record (made with G = 0.075 MPa, J_lim = 200,
# without noise) fitted back from the defaults G = 0.06, J_lim = 125 (to the 5 digits shown).
puncture_cli_test(fit_curve_manifest_cone
  STDOUT "  shear-modulus +0\\.075 \\+- ${number} MPa"
  STDOUT2 "  jlim +200 \\+- ${number}  95 %"
  STDOUT3 "cone, half-angle 30 deg, tip radius 0\\.2 mm, shank radius 2 mm"
  ARGS fit curve --manifest ${dir}/fit_curve_cone.toml --free shear-modulus,jlim)
puncture_cli_bad_input(fit_curve_manifest_cone_without_tip
  "fit_curve_cone_no_tip.toml:2 \\(test 1\\): invalid input:\n  --tip-radius: required with --indenter cone"
  fit curve --manifest ${dir}/fit_curve_cone_no_tip.toml --free jlim)
