'use strict';
// Lessons: the desktop's lesson files (datasets/lessons/, session/lessons/lessons.h), read by the
// desktop's reader inside the module, and played by the one lesson player of the teaching
// layer (session/lessons/lesson_player.h, Session.goToLessonStep): a step shows the same
// state and frame as on the desktop. A lesson's narrative and each step's caption show
// above the views. The claims are listed as the sentences they check; the check control
// (share.js checkClaims) measures the engine's claims on the page's lab, as `oflab-cli
// lesson check` does; the screen's are checked by `oflab --check-lesson`.

function loadLessons() {
  const lessons = JSON.parse(Module.Session.lessonsJson());
  if (lessons.error) {
    showMessage(`The shipped lessons could not be read: ${lessons.error}`);
    app.lessons = [];
  } else {
    app.lessons = lessons;
  }
  fillLessonPicker();
}

function fillLessonPicker() {
  const picker = $('lesson');
  while (picker.options.length > 1) picker.remove(1);
  for (const lesson of app.lessons) picker.add(new Option(lesson.title, lesson.name));
  picker.value = app.lesson ? app.lesson.name : '';
}

function startLesson(name) {
  app.lesson = app.lessons.find((l) => l.name === name) || null;
  $('lesson').value = app.lesson ? app.lesson.name : '';
  $('lesson-panel').hidden = !app.lesson;
  if (!app.lesson) {
    showMessage(name ? `There is no lesson '${name}' (lessons: ${app.lessons.map((l) => l.name).join(', ')})` : '');
    return;
  }
  showLessonStep(0);
}

// The lesson's narrative (step 0) or its k-th step, as the lesson player shows it: the
// lesson's state and frames played, then steps 1 .. k in turn.
function showLessonStep(k) {
  const lesson = app.lesson;
  if (!lesson) return;
  k = Math.max(0, Math.min(lesson.steps.length, k));
  const problem = app.session.goToLessonStep(lesson.name, k);
  if (problem) {
    showMessage(problem);
    return;
  }
  app.state = JSON.parse(app.session.stateJson());
  syncControls();
  showStateStudy(app.state);
  app.dirty = true;
  showMessage('');
  setPlaying(false);
  showLessonText(k);
}

// The lesson panel's text for part k of the lesson shown (0: the narrative): title, caption,
// the claims it checks; the check table is emptied until the check control is pressed.
function showLessonText(k) {
  const lesson = app.lesson;
  app.lessonStep = k;
  const step = k > 0 ? lesson.steps[k - 1] : null;
  $('lesson-title').textContent = lesson.title;
  $('lesson-caption').textContent = step ? step.say : lesson.narrative;
  $('lesson-step').textContent = k > 0 ? `step ${k} of ${lesson.steps.length}` : `narrative (${lesson.steps.length} steps)`;
  const claims = step ? step.claims : [];
  $('lesson-claims').innerHTML = claims.map((c) => `<li>checks: ${escapeHtml(c)}</li>`).join('');
  $('lesson-checks').hidden = true;
  $('lesson-checks').innerHTML = '';
  $('lesson-prev').disabled = k === 0;
  $('lesson-next').disabled = k === lesson.steps.length;
}

function escapeHtml(text) {
  return text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
}
