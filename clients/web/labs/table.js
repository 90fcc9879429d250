export default {id: 'table', title: 'table', mount(main) { main.textContent = 'table'; }};
