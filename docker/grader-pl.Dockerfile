# PrairieLearn external-grader image with mechd's offline evaluator: PrairieLearn's
# Python grader image plus /usr/local/bin/mechd-eval (the static build) and the
# external grading script of docs/grading/prairielearn (also shipped with the
# course in serverFilesCourse/mechd/, which PrairieLearn mounts at
# /grade/serverFilesCourse/mechd/ and the question's entrypoint runs).
#
#   make grader-image                     # builds mechd-grader, then this image
#   docker tag mechd-pl-grader YOUR-DOCKERHUB-USER/mechd-pl-grader:VERSION
#   docker push YOUR-DOCKERHUB-USER/mechd-pl-grader:VERSION
#
# then name it in the question's info.json ("externalGradingOptions": {"image": ...})
# and sync the image from the course's Sync page (docs/grading.md, "PrairieLearn").
ARG PL_BASE=prairielearn/grader-python
ARG MECHD_GRADER=mechd-grader
FROM ${MECHD_GRADER} AS mechd
FROM ${PL_BASE}
COPY --from=mechd /usr/local/bin/mechd-eval /usr/local/bin/mechd-eval
COPY docs/grading/prairielearn/serverFilesCourse/mechd/mechd_pl.py \
     docs/grading/prairielearn/serverFilesCourse/mechd/external_grade.py /opt/mechd/
ENV MECHD_EVAL=/usr/local/bin/mechd-eval
