/**
 * Recordings: the commands a run's car carried out, kept in a results folder for every run it lists as
 * a failure or a finding, so that the run can be replayed, drawn, animated and exported without its
 * controller ({@link sitcov.recording.Recording}, written and read by {@link sitcov.recording.RecordingFile},
 * found by row in a folder by {@link sitcov.recording.FolderRecordings}). RECORDINGS.md beside this file
 * documents the format and what it costs.
 */
package sitcov.recording;
