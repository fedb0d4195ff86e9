/**
 * The command line: {@link sitcov.cli.Main} and its commands, options, help and error messages.
 * The only place that calls {@code System.exit}.
 */
package sitcov.cli;
